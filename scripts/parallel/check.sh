#!/usr/bin/env bash
# Runs a `wai check` as N shards with GNU parallel — over the cores of one
# machine or over several hosts — and merges their records.
#
#   scripts/parallel/check.sh RUN_DIR N [options] -- CHECK_ARGS...
#
# Shard I writes RUN_DIR/shard-I.json (its record), RUN_DIR/shard-I.log
# (its output) and its counterexamples into RUN_DIR/counterexamples/; at
# the end `wai merge` writes RUN_DIR/merged.json, whole or marked partial.
# Run the same command again to resume: a shard runs only if RUN_DIR has
# no record of it, so a shard that failed, was killed (a record is written
# whole or not at all) or whose record was removed runs again, and the
# others are kept. RUN_DIR/joblog (GNU parallel's --joblog, appended) keeps
# every attempt: host, start, run time, exit status. Every shard of a run
# must come from one commit: the first call stores it in RUN_DIR/commit
# and later calls refuse another.
#
# Options:
#   --jobs J           shards at a time on each host (default: one per core,
#                      each shard on one thread; give --threads T in
#                      CHECK_ARGS and --jobs cores/T for more per shard)
#   --sshloginfile F   run the shards on the hosts of F (GNU parallel's
#                      format); every host needs this checkout at the same
#                      path, built, and RUN_DIR on a shared file system
#   --wai PATH         the wai binary (default target/release/wai)
#   --no-merge         leave the merge for later
#
# Exit status: 0 when the merge is whole, 1 when shards are missing (the
# merge is written, marked partial), 2 on bad usage, 3 otherwise.
set -euo pipefail
usage() { sed -n '2,30p' "$0" | sed 's/^# \{0,1\}//'; }
case "${1:-}" in -h|--help|"") usage; [ -n "${1:-}" ]; exit $? ;; esac
[ $# -ge 2 ] || { usage >&2; exit 2; }
run_dir=$1 shards=$2
shift 2
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "check.sh: N must be a positive whole number, not '$shards'" >&2; exit 2; }
jobs="" sshloginfile="" merge=1
repo=$(cd "$(dirname "$0")/../.." && pwd)
wai="$repo/target/release/wai"
while [ $# -gt 0 ]; do
  case "$1" in
    --jobs) jobs=$2; shift 2 ;;
    --sshloginfile) sshloginfile=$2; shift 2 ;;
    --wai) wai=$2; shift 2 ;;
    --no-merge) merge=0; shift ;;
    --) shift; break ;;
    *) echo "check.sh: unknown option $1 (the check's own arguments follow --)" >&2; exit 2 ;;
  esac
done
command -v parallel >/dev/null || { echo "check.sh: GNU parallel is not installed (Debian: apt-get install parallel)" >&2; exit 3; }
[ -x "$wai" ] || { echo "check.sh: no wai binary at $wai (cargo build --release -p wai-cli, or --wai PATH)" >&2; exit 3; }
for a in "$@"; do
  case "$a" in --shard|--shard=*|--record|--record=*|--out|--out=*)
    echo "check.sh: $a is set per shard by this script; leave it out" >&2; exit 2 ;;
  esac
done
mkdir -p "$run_dir/counterexamples"
run_dir=$(cd "$run_dir" && pwd)
commit=$(cd "$repo" && git rev-parse HEAD)
if [ -n "$(cd "$repo" && git status --porcelain --untracked-files=no)" ] && [ -z "${WAI_ALLOW_DIRTY:-}" ]; then
  echo "check.sh: $repo has uncommitted changes; a sharded run is made of one commit's shards (WAI_ALLOW_DIRTY=1 runs them anyway: the records then say +dirty, and a merge needs one binary)" >&2; exit 3
fi
if [ -f "$run_dir/commit" ] && [ "$(cat "$run_dir/commit")" != "$commit" ]; then
  echo "check.sh: $run_dir holds shards of commit $(cat "$run_dir/commit"), this checkout is at $commit; run the rest from a checkout of that commit (git worktree add DIR $(cat "$run_dir/commit"))" >&2
  exit 3
fi
echo "$commit" > "$run_dir/commit"
printf '%q ' "$@" > "$run_dir/args"

# One shard: its exit status 1 (a counterexample found and stored) is a
# finished shard; any other failure, or no record, is re-run on resume.
quoted=$(printf '%q ' "$@")
shard_cmd="cd $(printf '%q' "$repo") && r=\$($(printf '%q' "$wai") check $quoted --shard {}/$shards --record $(printf '%q' "$run_dir")/shard-{}.json --out $(printf '%q' "$run_dir")/counterexamples > $(printf '%q' "$run_dir")/shard-{}.log 2>&1; echo \$?); [ \"\$r\" -le 1 ] && [ -f $(printf '%q' "$run_dir")/shard-{}.json ]"
opts=(--joblog "+$run_dir/joblog" --line-buffer)
[ -n "$jobs" ] && opts+=(--jobs "$jobs")
[ -n "$sshloginfile" ] && opts+=(--sshloginfile "$sshloginfile")
todo=()
for i in $(seq 0 $((shards - 1))); do
  [ -f "$run_dir/shard-$i.json" ] || todo+=("$i")
done
echo "check.sh: $((shards - ${#todo[@]})) of $shards shards have a record; running ${#todo[@]}" >&2
status=0
if [ ${#todo[@]} -gt 0 ]; then
  printf '%s\n' "${todo[@]}" | parallel "${opts[@]}" "$shard_cmd" || status=$?
fi
echo "check.sh: shards done (GNU parallel status $status; $run_dir/joblog lists each attempt)" >&2
[ "$merge" = 1 ] || exit 0
shopt -s nullglob
records=("$run_dir"/shard-*.json)
[ ${#records[@]} -gt 0 ] || { echo "check.sh: no shard left a record; see $run_dir/shard-*.log" >&2; exit 3; }
"$wai" merge "${records[@]}" --record "$run_dir/merged.json"
