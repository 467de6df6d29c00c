#!/usr/bin/env bash
# Mutation testing over hand-picked faults (tools/mutants.tsv): each fault is applied, one at a time,
# to a private copy of the repository, the copy is built (Release) and the whole test suite is run.
# A fault is "killed" when the suite fails (or times out), "survived" when it passes, "no-build" when
# the mutated code does not compile. The working tree is never modified.
#
#   tools/mutate.sh                 run every fault
#   tools/mutate.sh T01 B04         run only these faults
#   tools/mutate.sh --check         only check that every fault applies (its text occurs exactly once)
#
# Environment: MUTATE_DIR (the copy; default a new temporary directory), MUTATE_TIMEOUT (seconds per
# test run, default 300), MUTATE_FILTER (a `dotnet test --filter` expression: only those tests run, for
# the baseline and every fault; cheaper on a busy machine. A fault the subset kills is killed by the
# whole suite too; one it lets through is reported "survived (filtered)" and must be run again without
# the filter before it is counted as a survivor). Results: one line per fault on stdout and in
# $MUTATE_DIR/results.tsv, then a score per folder and per area (the id's letters: T transition, S shapes,
# B BSP, W world, Q queries and casts, Y and V body, C object cull, M memos). Builds and test runs are
# sequential (one at a time).
set -euo pipefail

repo="$(cd "$(dirname "$0")/.." && pwd)"
list="$repo/tools/mutants.tsv"
check_only=0
ids=()
for arg in "$@"; do
  if [ "$arg" = "--check" ]; then check_only=1; else ids+=("$arg"); fi
done

work="${MUTATE_DIR:-$(mktemp -d "${TMPDIR:-/tmp}/acdream-mutate.XXXXXX")}"
timeout_s="${MUTATE_TIMEOUT:-300}"
copy="$work/repo"
mkdir -p "$copy"
# The tracked and untracked (not ignored) files of the working tree, so uncommitted tests count too.
(cd "$repo" && git ls-files -z -co --exclude-standard | tar --null -T - -cf -) | tar -xf - -C "$copy"
src="$copy/src/AcDream.Core.Physics"
tests="$copy/tests/AcDream.Core.Physics.Tests"

# apply FILE FIND REPLACE: replaces the single occurrence of FIND (\n and \t escapes) in FILE.
# Exit 3 when FIND does not occur exactly once.
apply() {
  FIND="$2" REPLACE="$3" perl -0777 -i -pe '
    BEGIN { ($f, $r) = map { my $s = $_; $s =~ s/\\n/\n/g; $s =~ s/\\t/\t/g; $s } ($ENV{FIND}, $ENV{REPLACE}); }
    my $n = () = /\Q$f\E/g;
    if ($n != 1) { print STDERR "found $n times\n"; exit 3; }
    s/\Q$f\E/$r/;
  ' "$1"
}

selected() {
  [ "${#ids[@]}" -eq 0 ] && return 0
  for x in "${ids[@]}"; do [ "$x" = "$1" ] && return 0; done
  return 1
}

# The baseline builds everything; a mutant rebuilds only the library (its public surface is unchanged,
# so nothing that references it needs recompiling) and copies it next to the tests.
build_all() { dotnet build "$tests" -c Release -nologo -v q >"$work/build.log" 2>&1; }
build() {
  dotnet build "$src/AcDream.Core.Physics.csproj" -c Release --no-restore -nologo -v q >"$work/build.log" 2>&1 &&
    cp "$src/bin/Release/net10.0/AcDream.Core.Physics.dll" "$tests/bin/Release/net10.0/"
}
# The whole suite; xUnit stops at the first failing test (a killed mutant needs no more).
filter=()
if [ -n "${MUTATE_FILTER:-}" ]; then filter=(--filter "$MUTATE_FILTER"); fi
run_tests() { timeout "$timeout_s" dotnet test "$tests" -c Release --no-build -nologo "${filter[@]}" -- xUnit.StopOnFail=true >"$work/test.log" 2>&1; }

if [ "$check_only" -eq 0 ]; then
  echo "copy: $copy"
  if ! build_all; then echo "the unmutated copy does not build; see $work/build.log" >&2; exit 1; fi
  if ! run_tests; then echo "the unmutated suite fails; see $work/test.log" >&2; exit 1; fi
  echo "baseline: builds and passes"
fi

results="$work/results.tsv"
: >"$results"
bad=0
while IFS=$'\t' read -r id file find replace what; do
  case "$id" in ''|'#'*) continue ;; esac
  selected "$id" || continue
  target="$src/$file"
  folder="${file%%/*}"
  if [ ! -f "$target" ]; then
    # A file moved or deleted: report it like a find that no longer matches, and go on to the next fault.
    echo "$id	$folder	not-applicable	no file $file" | tee -a "$results"
    bad=1
    continue
  fi
  cp "$target" "$work/original"
  if ! apply "$target" "$find" "$replace" 2>"$work/apply.log"; then
    echo "$id	$folder	not-applicable	$(cat "$work/apply.log")" | tee -a "$results"
    cp "$work/original" "$target"
    bad=1
    continue
  fi
  if [ "$check_only" -eq 1 ]; then
    cp "$work/original" "$target"
    continue
  fi
  if ! build; then
    outcome="no-build"; detail="$(grep -m1 -o 'error [A-Z0-9]*:.*' "$work/build.log" || true)"
  elif run_tests; then
    outcome="survived"; detail="$what"
    if [ "${#filter[@]}" -gt 0 ]; then detail="(filtered) $what"; fi
  else
    rc=$?
    outcome="killed"
    if [ "$rc" -eq 124 ]; then detail="timeout"; else detail="$(grep -m1 -oE 'Failed [A-Za-z0-9_.]+' "$work/test.log" || echo "suite failed")"; fi
  fi
  cp "$work/original" "$target"
  echo "$id	$folder	$outcome	$detail" | tee -a "$results"
done <"$list"

if [ "$check_only" -eq 1 ]; then
  [ "$bad" -eq 0 ] && echo "every fault applies"
  exit "$bad"
fi
# Score per folder and per area: killed / (killed + survived); faults that do not build or apply are not counted.
score() {
  awk -F'\t' -v key="$1" '
    { d = $2; if (key == "area") { d = $1; sub(/[0-9]+$/, "", d); d = "area " d } }
    $3 == "killed" { k[d]++ } $3 == "survived" { s[d]++ } { f[d] = 1 }
    END { for (d in f) { t = k[d] + s[d]; printf "%-22s killed %d of %d (%s)\n", d, k[d], t, t ? sprintf("%.0f %%", 100 * k[d] / t) : "-" } }
  ' "$results" | sort
}
echo
score folder
score area
