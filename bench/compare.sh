#!/usr/bin/env bash
# Measures the work tree against another commit in one run, on the same machine at the same time.
#
#   bench/compare.sh [--head COMMIT] BASE [PAIRS] [WORKLOAD...]                    wall-clock ratios
#   bench/compare.sh [--head COMMIT] --callgrind BASE [TRANSITIONS] [WORKLOAD...]  instruction counts
#   bench/compare.sh [--head COMMIT] --crowd BASE [PAIRS] [CREATURES...]            the crowd's ticks
#
# Builds the timing driver (bench/AcDream.Core.Physics.Timing, copied as it is in the work tree) once
# against BASE's library, in a temporary git worktree, and once against the work tree's library (or,
# with --head, against COMMIT's, in a second temporary worktree).
#
# Workloads (the driver's `list`): door-scene transitions, body steps (body-*, one PhysicsEngine.Step each) and
# world queries on the cottage (q-*, with q-resolve for scale); none named: all of them. Both fingerprints
# (transitions, body steps) are compared.
#
# Wall clock: runs the two builds alternately PAIRS times (default 5; the order swaps every pair) and
# prints, per workload, the median over the runs of each build's fastest sample (ns per transition), the
# bytes allocated per transition, and the ratio base / work tree (above 1: the work tree is faster).
#
# Callgrind: runs each workload under `valgrind --tool=callgrind` once per build: the driver resolves it 20
# times, then about TRANSITIONS transitions (default 2000) between two marks, and the instructions between
# the marks are divided by the transitions (start-up and JIT are left out). The JIT is asked for its optimized code at once
# (DOTNET_TieredCompilation=0) so the count is repeatable; it is a proxy for the tiered, profile-guided
# code that the wall-clock runs measure. A rough one: under valgrind the JIT compiles about half the
# methods, hot ones included, a second time with MinOpts (no inlining: they call Vector3's operators and
# span indexers; see docs/performance-history.md, "The face slide, this round"), so the counts overstate call
# overhead and understate what inlining saves; the wall-clock ratios decide. Default workloads: head-on
# and slide-ne. A workload named crowd-N counts the crowd's ticks instead (N creatures piling onto one
# player, the driver's `crowd-count N 270 30`: ticks 271-300, while the pile forms), per tick.
#
# Crowd: runs the driver's `crowd` command (N creatures, default 200 and 1000, on one thread) on the two builds
# alternately PAIRS times (default 3) and prints, per creature count and phase, the median over the runs of
# each build's mean tick, its worst 30-tick mean, and the ratio; and the crowd's fingerprints (every position
# of every tick) of both builds.
set -euo pipefail
crowd=0
callgrind=0
head_commit=
if [ "${1:-}" = "--head" ]; then head_commit=${2:?--head needs a commit}; shift 2; fi
if [ "${1:-}" = "--callgrind" ]; then callgrind=1; shift; fi
if [ "${1:-}" = "--crowd" ]; then crowd=1; shift; fi
base=${1:?usage: bench/compare.sh [--callgrind] BASE [PAIRS | TRANSITIONS] [WORKLOAD...]}
count=${2:-}
shift $(( $# < 2 ? $# : 2 ))
root=$(git rev-parse --show-toplevel)
driver=bench/AcDream.Core.Physics.Timing
tmp=$(mktemp -d)
cleanup() {
  git -C "$root" worktree remove --force "$tmp/base" >/dev/null 2>&1 || true
  git -C "$root" worktree remove --force "$tmp/head" >/dev/null 2>&1 || true
  rm -rf "$tmp"
}
trap cleanup EXIT

checkout() { # side commit: a temporary worktree of the commit, with the work tree's driver
  git -C "$root" worktree add --detach "$tmp/$1" "$2" >/dev/null 2>&1
  rm -rf "${tmp:?}/$1/$driver"
  mkdir -p "$tmp/$1/$driver"
  (cd "$root/$driver" && cp ./*.cs ./*.csproj "$tmp/$1/$driver/")
}
build() { # side source-root
  dotnet build -c Release "$2/$driver" -o "$tmp/out-$1" -v q -nologo >"$tmp/build-$1.log" 2>&1 || { cat "$tmp/build-$1.log" >&2; exit 1; }
}
checkout base "$base"
echo "building the driver against $(git -C "$root" rev-parse --short "$base") and against ${head_commit:-the work tree}" >&2
build base "$tmp/base"
if [ -n "$head_commit" ]; then
  checkout head "$head_commit"
  build head "$tmp/head"
else
  build head "$root"
fi

dll=AcDream.Core.Physics.Timing.dll
machine="machine: $(nproc) cores, $(uname -m), $(dotnet --list-runtimes | awk '/NETCore.App/ {v=$2} END {print ".NET " v}'), load average $(cut -d' ' -f1-3 /proc/loadavg)"
if [ -n "$head_commit" ]; then
  head_label="now $(git -C "$root" rev-parse --short "$head_commit")"
else
  head_label="now: work tree on $(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet HEAD -- src || echo ' (with changes)')"
fi

fp_base=$(dotnet "$tmp/out-base/$dll" fingerprint | awk '{printf "%s%s", (NR > 1 ? " " : ""), $2}')
fp_head=$(dotnet "$tmp/out-head/$dll" fingerprint | awk '{printf "%s%s", (NR > 1 ? " " : ""), $2}')
fingerprints="fingerprints (every result on the driver's approach grid; every body step on its body grid): base $fp_base, now $fp_head, $([ "$fp_base" = "$fp_head" ] && echo "bit-identical" || echo "DIFFERENT")"

if ((callgrind)); then
  transitions=${count:-2000}
  (($# > 0)) || set -- head-on slide-ne
  instructions() { # side workload runs -> instructions of the counted runs (the profile part between the driver's two marks)
    DOTNET_TieredCompilation=0 valgrind --tool=callgrind --dump-before=getpgrp --callgrind-out-file="$tmp/cg" \
      dotnet "$tmp/out-$1/$dll" count "$2" "$3" >/dev/null 2>&1
    awk '/^totals:/ { print $2 }' "$tmp/cg.2"
    rm -f "$tmp"/cg*
  }
  echo "base $(git -C "$root" rev-parse --short "$base"), $head_label; instructions per transition (callgrind, DOTNET_TieredCompilation=0)"
  echo "$machine"
  echo "$fingerprints"
  printf '%-14s %12s %12s %7s\n' workload "base Ir" "now Ir" ratio
  crowd_instructions() { # side creatures -> instructions of ticks 271-300
    DOTNET_TieredCompilation=0 valgrind --tool=callgrind --dump-before=getpgrp --callgrind-out-file="$tmp/cg" \
      dotnet "$tmp/out-$1/$dll" crowd-count "$2" 270 30 >/dev/null 2>&1
    awk '/^totals:/ { print $2 }' "$tmp/cg.2"
    rm -f "$tmp"/cg*
  }
  for w in "$@"; do
    if [[ $w == crowd-* ]]; then
      x=$(crowd_instructions base "${w#crowd-}"); y=$(crowd_instructions head "${w#crowd-}")
      awk -v w="$w" -v x="$x" -v y="$y" 'BEGIN { printf "%-14s %12d %12d %7.2f  (per tick, ticks 271-300)\n", w, x / 30, y / 30, x / y }'
      continue
    fi
    frames=$(dotnet "$tmp/out-head/$dll" list | awk -v w="$w" '$1 == w { print $2 }')
    [ -n "$frames" ] || { echo "unknown workload '$w'" >&2; exit 2; }
    runs=$(( (transitions + frames - 1) / frames ))
    declare -A per
    for side in base head; do
      per[$side]=$(awk -v a="$(instructions "$side" "$w" "$runs")" -v n=$((runs * frames)) 'BEGIN { printf "%.0f", a / n }')
    done
    awk -v w="$w" -v x="${per[base]}" -v y="${per[head]}" 'BEGIN { printf "%-14s %12d %12d %7.2f\n", w, x, y, x / y }'
  done
  exit 0
fi

if ((crowd)); then
  pairs=${count:-3}
  (($# > 0)) || set -- 200 1000
  for ((p = 1; p <= pairs; p++)); do
    if ((p % 2)); then order="base head"; else order="head base"; fi
    for side in $order; do
      dotnet "$tmp/out-$side/$dll" crowd --threads 1 "$@" | sed "s/^/$side /" >>"$tmp/results"
    done
    echo "pair $p of $pairs done ($(cut -d' ' -f1-3 /proc/loadavg))" >&2
  done
  echo "base $(git -C "$root" rev-parse --short "$base"), $head_label; $pairs runs each, median of each run's value, ms per tick"
  echo "$machine"
  echo "$fingerprints"
  awk '$8 == "fingerprint" { fp[$1, $3] = $9 } END { for (k in fp) { split(k, a, SUBSEP); printf "crowd %s creatures, %s: fingerprint %s\n", a[2], a[1], fp[k] } }' "$tmp/results" | sort
  printf '%-10s %-8s %-10s %9s %9s %7s\n' creatures phase value base now ratio
  awk '
    $6 == "forming" || $6 == "settled" { key = $3 " " $6 " mean"; add($1, key, $10) }
    $6 == "worst" { key = $3 " worst30 mean"; add($1, key, $9) }
    function add(side, key, v) { n[side, key]++; val[side, key, n[side, key]] = v; if (!(key in seen)) { seen[key] = 1; order[++k] = key } }
    function median(side, key,   i, j, m, t, a) {
      m = n[side, key]
      for (i = 1; i <= m; i++) a[i] = val[side, key, i]
      for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
      return m % 2 ? a[(m + 1) / 2] : (a[m / 2] + a[m / 2 + 1]) / 2
    }
    END { for (i = 1; i <= k; i++) { split(order[i], f, " "); b = median("base", order[i]); h = median("head", order[i]); printf "%-10s %-8s %-10s %9.3f %9.3f %7.2f\n", f[1], f[2], f[3], b, h, b / h } }' "$tmp/results"
  exit 0
fi

pairs=${count:-5}
for ((p = 1; p <= pairs; p++)); do
  if ((p % 2)); then order="base head"; else order="head base"; fi
  for side in $order; do
    dotnet "$tmp/out-$side/$dll" time "$@" | sed "s/^/$side /" >>"$tmp/results"
  done
  echo "pair $p of $pairs done" >&2
done

echo "base $(git -C "$root" rev-parse --short "$base"), $head_label; $pairs runs each, median of each run's fastest sample"
echo "$machine"
echo "$fingerprints"
printf '%-14s %12s %12s %9s %9s %7s\n' workload "base ns" "now ns" "base B" "now B" ratio
awk '{ key = $2; n[$1, key]++; v[$1, key, n[$1, key]] = $3; b[$1, key] = $4; if (!(key in seen)) { seen[key] = 1; order[++k] = key } }
function median(side, key,   i, j, m, t, a) {
  m = n[side, key]
  for (i = 1; i <= m; i++) a[i] = v[side, key, i]
  for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
  return m % 2 ? a[(m + 1) / 2] : (a[m / 2] + a[m / 2 + 1]) / 2
}
END {
  for (i = 1; i <= k; i++) {
    key = order[i]; mb = median("base", key); mh = median("head", key)
    printf "%-14s %12.1f %12.1f %9.1f %9.1f %7.2f\n", key, mb, mh, b["base", key], b["head", key], mb / mh
  }
}' "$tmp/results"
