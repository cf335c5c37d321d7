#!/usr/bin/env bash
# A verify campaign on Slurm, end to end (docs/campaigns.md): captures SCENES once through the GL
# driver, runs verify as a 4-task job array (scripts/slurm/verify-array.sbatch, `sbatch --wait`),
# merges the shards' reports, runs the same campaign unsharded outside Slurm, merges that, and
# compares the two merged reports byte for byte (cmp). Prints the time of each step.
#
#   scripts/slurm/run-campaign.sh SCENES_DIR WORK_DIR [TESSREF_BIN]
#
# Needs a running Slurm (scripts/slurm/setup-one-node.sh) and a tessref built with the GL runner.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
[ $# -ge 2 ] || { echo "usage: $0 SCENES_DIR WORK_DIR [TESSREF_BIN]" >&2; exit 2; }
SCENES="$(realpath "$1")"
work="$(realpath -m "$2")"
TESSREF_BIN="$(realpath "${3:-$here/../../build/cli/tessref}")"
[ -x "$TESSREF_BIN" ] || { echo "run-campaign: no tessref binary at $TESSREF_BIN" >&2; exit 2; }
export TESSREF_BIN SCENES CAPTURES="$work/captures" REPORTS="$work/reports-sharded"
rm -rf "$work"; mkdir -p "$work"
now() { date +%s.%N; }
took() { echo "run-campaign: $1: $(echo "$(now) - $2" | bc) s"; }

t=$(now)
"$TESSREF_BIN" capture "$SCENES" --out "$CAPTURES" >"$work/capture.log"
took "capture of $(ls "$SCENES"/*.json | wc -l) scenes" "$t"

t=$(now)
(cd "$work" && sbatch --wait --parsable --export=ALL "$here/verify-array.sbatch") >"$work/sbatch.log"
took "sbatch --wait, 4 array tasks (job $(cat "$work/sbatch.log"))" "$t"
cat "$work"/slurm-verify-*.out

rc=0
t=$(now)
"$TESSREF_BIN" verify --merge "$REPORTS" --json "$work/merged-sharded.json" --html "$work/site" || rc=$?
took "merge of the shards" "$t"
[ $rc -le 1 ] || exit $rc

t=$(now)
"$TESSREF_BIN" verify "$SCENES" --ref "$CAPTURES" --out "$work/reports-unsharded" || [ $? -le 1 ]
"$TESSREF_BIN" verify --merge "$work/reports-unsharded" --json "$work/merged-unsharded.json" >/dev/null || [ $? -le 1 ]
took "unsharded run (all threads) and merge" "$t"

if cmp "$work/merged-sharded.json" "$work/merged-unsharded.json"; then
  echo "run-campaign: cmp: the sharded and unsharded merged reports are identical ($(wc -c <"$work/merged-sharded.json") bytes)"
else
  echo "run-campaign: cmp: the merged reports DIFFER" >&2; exit 1
fi
echo "run-campaign: site at $work/site/index.html"
exit $rc
