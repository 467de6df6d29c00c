#!/usr/bin/env bash
# The determinism check on ARM64, under an emulator: publishes the determinism program
# (tests/AcDream.Core.Physics.Determinism) self-contained for linux-arm64, runs it under qemu-aarch64-static,
# runs the same program natively, and compares the two outputs line by line (every fuzz frame's raw bits,
# every built-in scene mover's hash, each fuzz case's input hash, PortableMath's results), and the native
# program once more with the hardware intrinsics off (the scalar fallbacks of the vector paths). It also checks
# the emulated run's area and scene lines against the committed x64 data (tests/.../Robustness/Determinism).
#
# Needs (installed when missing, on Debian, as root or through sudo): qemu-user-static and the arm64
# libc6, libstdc++6, libgcc-s1 and libssl3 (dpkg --add-architecture arm64). Installing libssl3:arm64 may
# upgrade the amd64 libssl3 to the same version (multiarch packages must match).
#
# Exit 0: identical. Exit 1: a difference (the first differing line is printed), or the check could not run
# (nothing is skipped silently). See docs/robustness.md, "Determinism".
set -euo pipefail
cd "$(dirname "$0")/.."
started=$(date +%s)
project=tests/AcDream.Core.Physics.Determinism/AcDream.Core.Physics.Determinism.csproj
data=tests/AcDream.Core.Physics.Tests/Robustness/Determinism
arm64_libs="libc6:arm64 libstdc++6:arm64 libgcc-s1:arm64 libssl3:arm64"

fail() {
  echo "check-arm64: FAILED: $*" >&2
  exit 1
}

have_emulator() {
  command -v qemu-aarch64-static >/dev/null 2>&1 &&
    [ -e /lib/ld-linux-aarch64.so.1 ] &&
    [ -e /usr/lib/aarch64-linux-gnu/libstdc++.so.6 ] &&
    [ -e /usr/lib/aarch64-linux-gnu/libgcc_s.so.1 ] &&
    [ -e /usr/lib/aarch64-linux-gnu/libssl.so.3 ]
}

install_emulator() {
  local as_root=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null 2>&1 || fail "qemu-user-static or the arm64 libraries are missing and this is not root (no sudo) to install them: $arm64_libs"
    as_root=(sudo -n)
  fi
  command -v apt-get >/dev/null 2>&1 || fail "qemu-user-static or the arm64 libraries are missing and there is no apt-get to install them (Debian or Ubuntu needed)"
  echo "check-arm64: installing the emulator and the arm64 runtime libraries"
  if ! dpkg --print-foreign-architectures | grep -qx arm64; then
    echo "+ dpkg --add-architecture arm64"
    "${as_root[@]}" dpkg --add-architecture arm64 || fail "dpkg --add-architecture arm64"
  fi
  echo "+ apt-get update"
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q || fail "apt-get update (is the package registry reachable?)"
  echo "+ apt-get install -y --no-install-recommends qemu-user-static $arm64_libs"
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends qemu-user-static $arm64_libs ||
    fail "apt-get install qemu-user-static $arm64_libs (an apt source limited to amd64, e.g. 'Architectures: amd64', has no arm64 packages)"
  have_emulator || fail "installed, but qemu-aarch64-static or an arm64 library is still missing"
}

if have_emulator; then
  echo "check-arm64: $(qemu-aarch64-static --version | head -n 1); arm64 libraries present"
else
  install_emulator
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "+ dotnet publish (linux-arm64, self-contained) and dotnet build (native)"
dotnet publish "$project" -c Release -r linux-arm64 --self-contained -o "$work/arm64" --artifacts-path "$work/artifacts-arm64" -v quiet -nologo ||
  fail "publishing the determinism program for linux-arm64"
dotnet build "$project" -c Release -o "$work/native" --artifacts-path "$work/artifacts-native" -v quiet -nologo ||
  fail "building the determinism program"
built=$(date +%s)

echo "+ native run"
t0=$(date +%s.%N)
dotnet "$work/native/AcDream.Core.Physics.Determinism.dll" >"$work/native.txt" || fail "the native run exited with $?"
t1=$(date +%s.%N)
# The vector paths' scalar fallbacks (taken where 128/256-bit vectors are not accelerated) on this machine too:
# the same program with the hardware intrinsics switched off must print the same values.
echo "+ native run, DOTNET_EnableHWIntrinsic=0 (the scalar fallbacks)"
DOTNET_EnableHWIntrinsic=0 dotnet "$work/native/AcDream.Core.Physics.Determinism.dll" >"$work/scalar.txt" || fail "the scalar run exited with $?"
if ! cmp -s <(grep -v '^#' "$work/native.txt") <(grep -v '^#' "$work/scalar.txt"); then
  echo "check-arm64: the vector and scalar paths differ on x64: $(cmp <(grep -v '^#' "$work/native.txt") <(grep -v '^#' "$work/scalar.txt") 2>&1 || true)" >&2
  exit 1
fi
echo "+ DOTNET_EnableWriteXorExecute=0 qemu-aarch64-static .../AcDream.Core.Physics.Determinism"
DOTNET_EnableWriteXorExecute=0 timeout 1200 qemu-aarch64-static "$work/arm64/AcDream.Core.Physics.Determinism" >"$work/arm64.txt" ||
  fail "the emulated ARM64 run exited with $? (stderr above)"
t2=$(date +%s.%N)
head -n 1 "$work/native.txt"
head -n 1 "$work/arm64.txt"
grep -q '^# acdream determinism: Arm64' "$work/arm64.txt" || fail "the emulated run did not report Arm64"
grep '^# platform\.' "$work/arm64.txt" | sed 's/^# /arm64 /' || true

# Line by line, '#' lines (run descriptions, platform maths) aside.
grep -v '^#' "$work/native.txt" >"$work/native.values"
grep -v '^#' "$work/arm64.txt" >"$work/arm64.values"
lines=$(wc -l <"$work/native.values")
[ "$lines" -gt 1000 ] || fail "the native run printed only $lines lines"
if ! cmp -s "$work/native.values" "$work/arm64.values"; then
  message=$(cmp "$work/native.values" "$work/arm64.values" 2>&1 || true)
  case "$message" in
    *EOF*) echo "check-arm64: x64 and ARM64 printed different numbers of lines: $message" >&2 ;;
    *)
      line=$(echo "$message" | sed -n 's/.*line \([0-9]*\).*/\1/p')
      echo "check-arm64: x64 and ARM64 differ; first difference at line $line (on an input.* line the fuzz case itself was generated differently):" >&2
      echo "  x64:   $(sed -n "${line}p" "$work/native.values")" >&2
      echo "  arm64: $(sed -n "${line}p" "$work/arm64.values")" >&2
      ;;
  esac
  exit 1
fi

# The emulated run against the committed x64 data, file by file.
for file in "$data"/area.*.X64.txt "$data"/scene.*.X64.txt; do
  stem=$(basename "$file" .X64.txt)
  if ! diff -q <(grep "^$stem	" "$work/arm64.values" | cut -f2-) <(grep -v '^$' "$file") >/dev/null; then
    echo "check-arm64: the ARM64 lines of $stem differ from the committed $(basename "$file"):" >&2
    diff <(grep -v '^$' "$file") <(grep "^$stem	" "$work/arm64.values" | cut -f2-) | head -n 4 >&2
    exit 1
  fi
done

finished=$(date +%s)
awk -v lines="$lines" -v t0="$t0" -v t1="$t1" -v t2="$t2" -v build="$((built - started))" -v total="$((finished - started))" 'BEGIN {
  printf "check-arm64: ok, %d lines bit-identical on x64 and ARM64 (and the committed x64 data); native run %.1f s, emulated %.1f s, install and build %d s, total %d s\n", lines, t1 - t0, t2 - t1, build, total }'
