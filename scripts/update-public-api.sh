#!/usr/bin/env bash
# Regenerates the public API baselines (PublicAPI.Unshipped.txt) of both library projects from the code: the
# runtime (src/AcDream.Core.Physics) first, then the tooling that references it (src/AcDream.Core.Physics.Scenes).
# Every public symbol not already in the project's PublicAPI.Shipped.txt is listed, stale entries disappear.
# Run it after an intended change of the public surface (or after a merge), then review the diff.
set -euo pipefail
cd "$(dirname "$0")/.."
for name in AcDream.Core.Physics AcDream.Core.Physics.Scenes AcDream.Core.Physics.Dat; do
  project="src/$name/$name.csproj"
  unshipped="src/$name/PublicAPI.Unshipped.txt"
  # Start from an empty list so removed or changed symbols do not linger (RS0017 has no automatic fix).
  printf '#nullable enable\n' > "$unshipped"
  # The analyzer's code fix for RS0016 adds each missing public symbol.
  dotnet format analyzers "$project" --diagnostics RS0016 --severity warn
  # A stable order keeps diffs small and merges simple.
  { printf '#nullable enable\n'; grep -v '^#nullable enable$' "$unshipped" | LC_ALL=C sort -u; } > "$unshipped.tmp"
  mv "$unshipped.tmp" "$unshipped"
  echo "$(grep -vc '^#' "$unshipped") public symbols in $unshipped"
done
