#!/bin/sh
# Cost against sphere count (docs/performance.md): random scenes (tools/sphere-scenes.py random N) at 320×240,
# 2 threads, renderMs (the median of 3 runs; one run where a render takes over 5 s) of jittered 16, adaptive at its
# defaults and exact, each with the hierarchy ("auto") and with "acceleration": "none"; a run whose process (start-up,
# the JIT build's warm-up render and the timed one: about 2 × renderMs) takes over 60 s is cut off ("> 60 s"), and
# a column stops at its first cut-off; "refused": raylab stopped with its one-line error (the exact sampler draws at most
# 20 000 spheres in view), and the column stops there too. Writes docs/sphere-count.csv, docs/sphere-count.md (the
# table) and the log-log chart docs/sphere-count.png + .svg (raylab's hidden `chart` command, the library's
# LogLogChart). Usage, from the repository's folder after a Release build:
#   sh tools/sphere-count.sh [RAYLAB] [COUNTS]      e.g. sh tools/sphere-count.sh "" "1 10 100"
R=${1:-samples/RayLab.Console/bin/Release/net10.0/raylab}
COUNTS=${2:-"1 3 10 30 100 300 1000 3000 10000 30000 100000"}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
# ms FILE ARGS: the median renderMs of up to 3 runs, "> 60 s" (cut off by the timeout) or "refused" (raylab
# stopped with its one-line error, e.g. the exact sampler's limit of spheres in view)
ms() {
  f=$1; shift
  runs=""
  for i in 1 2 3; do
    timeout 60 "$R" render "$f" -o "$T/x.png" --threads 2 --stats "$T/s.json" --warmup "$@" >/dev/null 2>&1
    status=$?
    [ $status -eq 124 ] && { echo "> 60 s"; return; }
    [ $status -ne 0 ] && { echo "refused"; return; }
    v=$(python3 -c "import json;print(json.load(open('$T/s.json'))['renderMs'])")
    runs="$runs $v"
    python3 -c "import sys; sys.exit(0 if $v > 5000 else 1)" && break
  done
  python3 -c "import statistics,sys; print(round(statistics.median(float(x) for x in sys.argv[1:]), 1))" $runs
}
SAMPLERS="jittered:--sampler jittered --samples 16|adaptive:--sampler adaptive|exact:--sampler exact"
echo "spheres,jittered 16,jittered 16 (none),adaptive,adaptive (none),exact,exact (none)" > "$T/table.csv"
cut=""   # the columns already cut off or refused (a later, larger count repeats the column's last word)
for n in $COUNTS; do
  python3 tools/sphere-scenes.py random "$n" "$T/on.json"
  python3 tools/sphere-scenes.py random "$n" "$T/off.json" 1 --no-acceleration
  row="$n"
  column=0
  IFS='|'
  for s in $SAMPLERS; do
    args=${s#*:}
    for f in on off; do
      column=$((column + 1))
      IFS=' '
      case " $cut " in
        *" $column "*) eval "v=\$word_$column" ;;
        *) v=$(ms "$T/$f.json" $args) ;;
      esac
      IFS='|'
      case "$v" in "> 60 s"|refused) cut="$cut $column"; eval "word_$column=\$v" ;; esac
      row="$row,$v"
    done
  done
  unset IFS
  echo "$row" >> "$T/table.csv"
  echo "$row" >&2
done
mkdir -p docs
cp "$T/table.csv" docs/sphere-count.csv
python3 - docs/sphere-count.csv > docs/sphere-count.md <<'EOF'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
print("| " + " | ".join(rows[0]) + " |")
print("|" + "|".join("---:" for _ in rows[0]) + "|")
for r in rows[1:]:
    print("| " + " | ".join(c if c.startswith(">") or c == "refused" else f"{float(c):,.1f}".replace(",", " ") if i else f"{int(c):,}".replace(",", " ") for i, c in enumerate(r)) + " |")
EOF
cat docs/sphere-count.md
"$R" chart docs/sphere-count.csv --out docs/sphere-count --title "Render time against sphere count (320×240, 2 threads)" \
  --x-label "spheres" --y-label "renderMs (ms)"
