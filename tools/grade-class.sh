#!/usr/bin/env bash
# How long `raylab grade` takes for a class: N exercise labs made by raylab-lab-solution (the reference solution, so
# every row must read "ok" with every section "pass"), graded in bubblewrap against a kit's pinned checks.
# Usage: tools/grade-class.sh KIT N JOBS [WORK]
#   KIT   a class kit (tools/class-kit.sh DIR --feed-only is enough)
#   N     how many labs
#   JOBS  raylab grade's --jobs
#   WORK  the folder for the labs and the report (default: a fresh temporary folder, removed at the end)
# Prints raylab grade's own lines, then one line: "N labs, --jobs J: S s wall, R rows ok, P sections pass of T".
# Needs the checkout's Debug build (dotnet build RayLab.sln) and bubblewrap.
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: tools/grade-class.sh KIT N JOBS [WORK]" >&2
  exit 2
fi
repo=$(cd "$(dirname "$0")/.." && pwd)
kit=$(cd "$1" && pwd)
count=$2
jobs=$3
if [ $# -ge 4 ]; then
  work=$(mkdir -p "$4" && cd "$4" && pwd)
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
raylab="$repo/samples/RayLab.Console/bin/Debug/net10.0/raylab.dll"
[ -f "$raylab" ] || { echo "grade-class: no $raylab: dotnet build RayLab.sln first" >&2; exit 1; }

# The template from the kit, in a dotnet home of this run's own.
export DOTNET_CLI_HOME="$work/dotnet-home" NUGET_PACKAGES="$work/nuget-packages"
mkdir -p "$DOTNET_CLI_HOME" "$work/subs"
template=$(ls "$kit"/instructor/RayLab.Templates.Instructor.*.nupkg)
version=$(basename "$template" .nupkg)
version=${version#RayLab.Templates.Instructor.}
dotnet new install "RayLab.Templates.Instructor::$version" --add-source "$kit/instructor" > /dev/null
for i in $(seq -w 1 "$count"); do
  dotnet new raylab-lab-solution -o "$work/subs/student$i" --kind exercise --feed "$kit/feed" --offline --skipRestore > /dev/null
done

start=$SECONDS
dotnet "$raylab" grade "$work/subs" --checks "$kit/checks/exercise" --out "$work/report" --jobs "$jobs"
wall=$((SECONDS - start))
python3 - "$work/report/grades.json" "$count" "$jobs" "$wall" <<'EOF'
import json, sys
grades = json.load(open(sys.argv[1]))
rows = grades["students"]
ok = sum(r["status"] == "ok" for r in rows)
results = [v for r in rows for v in r["sections"].values()]
print(f"{sys.argv[2]} labs, --jobs {sys.argv[3]}: {sys.argv[4]} s wall, {ok} rows ok, "
      f"{sum(v == 'pass' for v in results)} sections pass of {len(results)}")
EOF
