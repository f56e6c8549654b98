#!/usr/bin/env bash
# tests/third_party_body/build.sh - build Towfish.fmu, a towed body FMU of "another vendor", outside the
# project's CMake: the C compiler on towfish.c (with the FMI 2.0 headers), the FMU zipped by Python.
#
#   bash tests/third_party_body/build.sh [OUT_DIR]      (default: build/third_party_body)
#
# Writes OUT_DIR/Towfish.fmu (modelDescription.xml, binaries/linux64/Towfish.so).
set -euo pipefail

case "${1:-}" in
  -h|--help) sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
esac

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
OUT="$(mkdir -p "${1:-$ROOT/build/third_party_body}" && cd "${1:-$ROOT/build/third_party_body}" && pwd)"
STAGE="$(mktemp -d)"
trap 'rm -rf "$STAGE"' EXIT

mkdir -p "$STAGE/binaries/linux64"
"${CC:-cc}" -std=c99 -O2 -Wall -Wextra -Werror -fPIC -shared -fvisibility=hidden \
  -I"$ROOT/fmu" -o "$STAGE/binaries/linux64/Towfish.so" "$HERE/towfish.c" -lm
cp "$HERE/modelDescription.xml" "$STAGE/"
rm -f "$OUT/Towfish.fmu"
(cd "$STAGE" && python3 -m zipfile -c "$OUT/Towfish.fmu" modelDescription.xml binaries)
echo "built: $OUT/Towfish.fmu"
