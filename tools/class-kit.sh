#!/usr/bin/env bash
# The class kit: one folder that hands out the lab with no network and grades it (docs/teaching.md).
#   DIR/feed/              what the students get: every package a new lab restores: RayLab, RayLab.Reports,
#                          RayLab.ImageSharp (when the repository has it), RayLab.Templates (no reference solution in
#                          it), the RayLab.Tool packages, and xUnit, the test SDK, SixLabors.ImageSharp, … with their
#                          dependencies, copied from a fresh NuGet cache after restoring a lab of every kind
#   DIR/instructor/        the instructor's template package, RayLab.Templates.Instructor (`dotnet new
#                          raylab-lab-solution`: the exercise lab with its reference solution), kept out of feed/
#   DIR/checks/KIND/       the instructor's pinned checks: a lab of that kind as the templates make it (the exercise
#                          lab from raylab-lab-solution, with its reference solution); `raylab grade` replaces each
#                          submission's tests/Lab.Tests and root build files with these
#   DIR/raylab-linux-x64/  the native raylab (as tools/publish-native.sh makes it), which also grades
#   DIR/playground/        the published playground site (samples/RayLab.Web), for any static host
#   DIR/README.md          the instructor's page, Polish and English (docs/teaching.md is the long form)
# Usage: tools/class-kit.sh DIR [--feed-only] [--packed FOLDER]
#   --feed-only       the feed (without the tool packages), instructor/ and the checks alone: what a lab needs (the CI
#                     test uses it)
#   --packed FOLDER   this checkout's packages are already packed (all of one version) in FOLDER: copied from there
#                     instead of packed again (the template tests pass the run's one packing)
# Needs the .NET SDK and network access to a NuGet source for xUnit & co. (the machine's own sources), and for the
# native build a C toolchain (clang or gcc) and unzip (or python3).
set -euo pipefail
usage="usage: tools/class-kit.sh DIR [--feed-only] [--packed FOLDER]"
if [ $# -lt 1 ] || [ "${1:0:1}" = "-" ]; then
  echo "$usage" >&2
  exit 2
fi
repo=$(cd "$(dirname "$0")/.." && pwd)
kit_arg=$1
shift
full=1
packed=
while [ $# -gt 0 ]; do
  case "$1" in
    --feed-only) full=0 ;;
    --packed)
      if [ $# -lt 2 ] || [ ! -d "$2" ]; then echo "tools/class-kit.sh: --packed needs a folder that exists" >&2; exit 2; fi
      packed=$(cd "$2" && pwd); shift ;;
    *) echo "tools/class-kit.sh: unknown option '$1'; $usage" >&2; exit 2 ;;
  esac
  shift
done
mkdir -p "$kit_arg"
kit=$(cd "$kit_arg" && pwd)
if [ -n "$(ls -A "$kit")" ]; then
  echo "tools/class-kit.sh: $kit is not empty; give an empty or new folder" >&2
  exit 1
fi
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1 DOTNET_SKIP_FIRST_TIME_EXPERIENCE=1 DOTNET_GENERATE_ASPNET_CERTIFICATE=false
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
feed="$kit/feed"
mkdir -p "$feed"

projects=(src/RayLab src/RayLab.Reports src/RayLab.Grading.Uses src/RayLab.Grading templates/RayLab.Templates)
[ -d "$repo/src/RayLab.ImageSharp" ] && projects+=(src/RayLab.ImageSharp)
# The tool: the pointer package, the framework-dependent build every OS runs, and the native linux-x64 build.
tool_ids=(RayLab.Tool RayLab.Tool.any RayLab.Tool.linux-x64)
if [ -n "$packed" ]; then
  # (the version is the instructor's package's: no other package's id starts with its id)
  instructor=$(ls "$packed"/RayLab.Templates.Instructor.[0-9]*.nupkg 2>/dev/null || true)
  if [ "$(wc -w <<<"$instructor")" -ne 1 ]; then
    echo "tools/class-kit.sh: not one RayLab.Templates.Instructor.<version>.nupkg in $packed" >&2
    exit 1
  fi
  version=$(basename "$instructor" .nupkg); version=${version#RayLab.Templates.Instructor.}
  ids=()
  for p in "${projects[@]}"; do ids+=("$(basename "$p")"); done
  [ $full = 1 ] && ids+=("${tool_ids[@]}")
  echo "== packages of this checkout, packed at $version in $packed -> $feed"
  for id in "${ids[@]}"; do
    if [ ! -e "$packed/$id.$version.nupkg" ]; then
      echo "tools/class-kit.sh: $packed has no $id.$version.nupkg" >&2
      exit 1
    fi
    cp "$packed/$id.$version.nupkg" "$feed/"
  done
  echo "== the instructor's template package -> $kit/instructor"
  mkdir -p "$kit/instructor"
  cp "$instructor" "$kit/instructor/"
else
  echo "== packages of this checkout -> $feed"
  for p in "${projects[@]}"; do
    dotnet pack "$repo/$p" -c Release -o "$feed" --artifacts-path "$work/artifacts" -v q -nologo
  done
  # The reference solution's package goes beside the feed, not in it: feed/ is what the students get.
  echo "== the instructor's template package -> $kit/instructor"
  dotnet pack "$repo/templates/RayLab.Templates.Instructor" -c Release -o "$kit/instructor" --artifacts-path "$work/artifacts" -v q -nologo
  if [ $full = 1 ]; then
    dotnet pack "$repo/samples/RayLab.Console" -c Release -o "$feed" -v q -nologo
    dotnet pack "$repo/samples/RayLab.Console" -c Release -r any -o "$feed" -v q -nologo
    dotnet pack "$repo/samples/RayLab.Console" -c Release -r linux-x64 -o "$feed" -v q -nologo
  fi
fi
template=$(ls "$feed"/RayLab.Templates.[0-9]*.nupkg)
version=$(basename "$template" .nupkg); version=${version#RayLab.Templates.}
# One version for all (MinVer: the commit's); a commit made while packing would split them.
for p in "${projects[@]}" templates/RayLab.Templates.Instructor; do
  id=$(basename "$p")
  [ "$id" = RayLab.Templates.Instructor ] && dir="$kit/instructor" || dir="$feed"
  if [ ! -e "$dir/$id.$version.nupkg" ]; then
    echo "tools/class-kit.sh: $id was not packed at the templates' version $version (a commit during the run?); make the kit again" >&2
    exit 1
  fi
done

echo "== a lab of every kind, restored into an empty NuGet cache: its packages go into the feed"
export DOTNET_CLI_HOME="$work/home" NUGET_PACKAGES="$work/packages"
mkdir -p "$DOTNET_CLI_HOME" "$NUGET_PACKAGES"
dotnet new install "RayLab.Templates::$version" --add-source "$feed" >/dev/null
dotnet new install "RayLab.Templates.Instructor::$version" --add-source "$kit/instructor" >/dev/null
# The kinds this template offers: the exercise lab (from raylab-lab-solution, with its reference solution: the checks'
# oracle) where the template has --kind, else the method lab alone.
if dotnet new raylab-lab --help 2>/dev/null | grep -q -- '--kind'; then
  kinds=(exercise method)
else
  kinds=(method)
fi
labs="$work/labs"
for kind in "${kinds[@]}"; do
  args=(-o "$labs/$kind" -n MyLab --feed "$feed" --skipRestore)
  [ ${#kinds[@]} -gt 1 ] && args+=(--kind "$kind")
  template=raylab-lab
  [ "$kind" = exercise ] && template=raylab-lab-solution
  dotnet new "$template" "${args[@]}" >/dev/null
  # Restoring the checks restores the whole lab (they reference src/Lab); the method option's two kinds of
  # MyMethod.cs use the same packages.
  dotnet restore "$labs/$kind/tests/Lab.Tests" -v q -nologo
  # The pinned checks: the template's lab of this kind, without its nuget.config (the grader writes its own).
  mkdir -p "$kit/checks"
  cp -r "$labs/$kind" "$kit/checks/$kind"
  rm -rf "$kit/checks/$kind/nuget.config" "$kit/checks/$kind"/*/*/bin "$kit/checks/$kind"/*/*/obj
  if [ "$kind" = method ]; then
    pictures='"orthographic": "out/two-spheres-orthographic-mymethod.png", "perspective": "out/two-spheres-perspective-mymethod.png"'
    timed=mymethod
  else
    pictures='"orthographic": "out/two-spheres-orthographic.png", "perspective": "out/two-spheres-perspective.png"'
    timed=adaptive
  fi
  cat > "$kit/checks/$kind/grading.json" <<EOF
{
  "kind": "$kind",
  "raylabVersion": "$version",
  "pictures": { $pictures },
  "timedMethod": "$timed"
}
EOF
done
# RayLab.ImageSharp and what it needs (SixLabors.ImageSharp), for a lab that adds the package itself.
if ls "$feed"/RayLab.ImageSharp.*.nupkg >/dev/null 2>&1; then
  mkdir -p "$work/imagesharp"
  cat > "$work/imagesharp/nuget.config" <<EOF
<configuration><packageSources><add key="kit" value="$feed" /></packageSources></configuration>
EOF
  cat > "$work/imagesharp/ImageSharpLab.csproj" <<EOF
<Project Sdk="Microsoft.NET.Sdk">
  <PropertyGroup><TargetFramework>net10.0</TargetFramework></PropertyGroup>
  <ItemGroup><PackageReference Include="RayLab.ImageSharp" Version="$version" /></ItemGroup>
</Project>
EOF
  dotnet restore "$work/imagesharp" -v q -nologo
fi
# (the cache names files in lower case; NuGet's ids are case-insensitive, so a package already packed here is skipped)
have=$(ls "$feed" | tr '[:upper:]' '[:lower:]')
for nupkg in "$NUGET_PACKAGES"/*/*/*.nupkg; do
  grep -qxF "$(basename "$nupkg")" <<<"$have" || cp "$nupkg" "$feed/"
done
rm -f "$feed"/*.snupkg
dotnet new uninstall RayLab.Templates >/dev/null
dotnet new uninstall RayLab.Templates.Instructor >/dev/null

if [ $full = 1 ]; then
  # The native tool package holds what tools/publish-native.sh makes (raylab, the launcher; raylab-x86-64-v2, -v3, -v4;
  # scenes/): unpacked from it rather than compiled three times more.
  echo "== the native raylab (linux-x64, from RayLab.Tool.linux-x64) -> $kit/raylab-linux-x64"
  mkdir -p "$work/native"
  if command -v unzip >/dev/null; then
    unzip -q "$feed/RayLab.Tool.linux-x64.$version.nupkg" -d "$work/native"
  else
    python3 -m zipfile -e "$feed/RayLab.Tool.linux-x64.$version.nupkg" "$work/native"
  fi
  entry=$(find "$work/native" -type f -name raylab | head -n 1)
  cp -r "$(dirname "$entry")" "$kit/raylab-linux-x64"
  chmod +x "$kit/raylab-linux-x64"/raylab*
  echo "== the playground -> $kit/playground"
  dotnet publish "$repo/samples/RayLab.Web" -c Release -o "$work/web" -v q -nologo
  cp -r "$work/web/wwwroot" "$kit/playground"
fi

cp "$repo/tools/class-kit/README.md" "$kit/README.md"
sed -i "s/RAYLAB_KIT_VERSION/$version/g" "$kit/README.md"
if [ $full = 0 ]; then
  # The README describes the full kit; say what this one lacks, in both of its languages, under its title.
  sed -i '1a\
\
> **Zestaw `--feed-only`:** bez `raylab-linux-x64/` i `playground/`, a w `feed/` nie ma `RayLab.Tool`; oceniaj z folderu\
> repozytorium: `dotnet run --project samples/RayLab.Console -- grade …`. **A `--feed-only` kit:** no `raylab-linux-x64/`\
> or `playground/`, and no `RayLab.Tool` in `feed/`; grade from the repository folder with\
> `dotnet run --project samples/RayLab.Console -- grade …`.' "$kit/README.md"
fi
echo "$kit: RayLab $version, $(ls "$feed" | wc -l) packages in feed/ (hand out), instructor/ and checks: ${kinds[*]} (keep)$([ $full = 1 ] && echo ', raylab-linux-x64/, playground/')"
