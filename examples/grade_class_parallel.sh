#!/bin/sh
# examples/grade_class_parallel.sh — grade a class on one machine, one labgrade
# process per student, JOBS at a time (GNU parallel), then merge their CSVs
# into one. The same split spreads a class over many machines (README.md,
# "A class on many machines"): there each job runs on another node.
#
#   examples/grade_class_parallel.sh CLASS_DIR OUT_DIR JOBS [labgrade options...]
#
# CLASS_DIR holds one folder per student (a source tree, a build or images).
# OUT_DIR gets one/<student>/ (a class of one: a link to the submission),
# csv/<student>.csv and class.csv, the merged table (one header, a row per
# student, in name order). The labgrade options (e.g. --labs 12
# --hidden 2 --seed 7 --work DIR) go to every process; give every process the
# same --work folder: they share its compiler cache and hidden references, and
# labgrade locks what they make together.
# LABGRADE names the program (default: build/bin/labgrade beside this folder).
# Exit status: 0 when every student passed everything, 1 when some did not,
# 2 when a labgrade process or this script could not do its work.
set -eu
if [ $# -lt 3 ]; then
    echo "usage: $0 CLASS_DIR OUT_DIR JOBS [labgrade options...]" >&2
    exit 2
fi
class=$(cd "$1" && pwd) || exit 2
out=$2
jobs=$3
shift 3
here=$(cd "$(dirname "$0")/.." && pwd)
labgrade=${LABGRADE:-$here/build/bin/labgrade}
command -v parallel >/dev/null 2>&1 || { echo "$0: GNU parallel is not installed (Debian: parallel)" >&2; exit 2; }
[ -x "$labgrade" ] || { echo "$0: no labgrade at $labgrade (build it, or set LABGRADE)" >&2; exit 2; }
mkdir -p "$out/one" "$out/csv"
out=$(cd "$out" && pwd)

# One job per student folder; a job's status is labgrade's (0, 1 or 2).
# --halt never: a failing student does not stop the others.
status=0
find -L "$class" -mindepth 1 -maxdepth 1 -type d -printf '%f\n' | sort |
    parallel -j "$jobs" --halt never \
        "mkdir -p '$out/one/{}' && ln -sfn '$class/{}' '$out/one/{}/{}' && \
         '$labgrade' --class '$out/one/{}' --csv '$out/csv/{}.csv' --quiet $*" || status=$?

# parallel exits with the number of failed jobs (at most 101); a job that
# exited 2 left no CSV.
for dir in "$out"/one/*/; do
    student=$(basename "$dir")
    [ -f "$out/csv/$student.csv" ] || { echo "$0: $student was not graded (see above)" >&2; exit 2; }
done
first=$(find "$out/csv" -name '*.csv' | sort | head -n 1)
{ head -n 1 "$first"; find "$out/csv" -name '*.csv' | sort | xargs tail -q -n +2; } > "$out/class.csv"
echo "$(($(wc -l < "$out/class.csv") - 1)) students: $out/class.csv"
[ "$status" -eq 0 ] || exit 1
