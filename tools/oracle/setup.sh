#!/usr/bin/env bash
# Sets up Microsoft's shader compiler as ps30's test oracle (docs/oracle.md):
#
#   tools/oracle/setup.sh [DIR]      DIR defaults to target/oracle (ignored by git)
#
# - Debian's wine64 and gcc-mingw-w64-x86-64, installed with apt-get when missing;
# - d3dcompiler_47.dll, taken from the PyQt5-Qt5 5.15.2 win_amd64 wheel on PyPI (Qt ships
#   Microsoft's redistributable DLL there) and checked against the SHA-256 below: the
#   fixtures are this DLL's answers, and another build may answer otherwise;
# - DIR/harness.exe, built from tools/oracle/harness.c when missing or older than it;
# - DIR/prefix, the Wine prefix the harness runs in.
#
# Each step is skipped when already done, so a second run takes a moment. The DLL is never
# committed: it stays in DIR. Exit status 0 when the oracle is ready, 1 otherwise.
set -euo pipefail

DLL_SHA256=e994847e01a6f1e4cbdc5a864616ac262f67ee4f14db194984661a8d927ab7f4
WHEEL=PyQt5-Qt5==5.15.2
DLL_IN_WHEEL=PyQt5/Qt5/bin/d3dcompiler_47.dll

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
dir=${1:-$root/target/oracle}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)

fail() {
    echo "tools/oracle/setup.sh: $*" >&2
    exit 1
}

sha256_of() {
    sha256sum "$1" | cut -d' ' -f1
}

# 1. Wine and MinGW.
if ! command -v wine >/dev/null || ! command -v x86_64-w64-mingw32-gcc >/dev/null; then
    command -v apt-get >/dev/null || fail "needs wine and x86_64-w64-mingw32-gcc (Debian: wine64, gcc-mingw-w64-x86-64)"
    echo "installing wine64 and gcc-mingw-w64-x86-64 ..." >&2
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq wine64 gcc-mingw-w64-x86-64 >/dev/null
fi

# 2. The DLL, fetched once and checked every time.
dll=$dir/d3dcompiler_47.dll
if [ ! -f "$dll" ]; then
    echo "fetching d3dcompiler_47.dll from the $WHEEL win_amd64 wheel ..." >&2
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    python3 -m pip download -q --no-deps --platform win_amd64 --only-binary=:all: \
        "$WHEEL" -d "$tmp" || fail "pip could not download $WHEEL for win_amd64"
    wheel=$(ls "$tmp"/PyQt5_Qt5-*.whl 2>/dev/null | head -n1)
    [ -n "$wheel" ] || fail "pip downloaded no PyQt5_Qt5 wheel"
    python3 - "$wheel" "$DLL_IN_WHEEL" "$dll.part" <<'EOF'
import sys, zipfile
wheel, member, out = sys.argv[1:]
with zipfile.ZipFile(wheel) as z, open(out, "wb") as f:
    f.write(z.read(member))
EOF
    mv "$dll.part" "$dll"
fi
got=$(sha256_of "$dll")
if [ "$got" != "$DLL_SHA256" ]; then
    fail "$dll has SHA-256 $got, not $DLL_SHA256: the fixtures are that build's answers. Remove the file to fetch it again."
fi

# 3. The harness, rebuilt when its source is newer.
exe=$dir/harness.exe
if [ ! -f "$exe" ] || [ "$here/harness.c" -nt "$exe" ]; then
    x86_64-w64-mingw32-gcc -O2 -Wall -Werror -o "$exe.part" "$here/harness.c" \
        || fail "the harness does not build"
    mv "$exe.part" "$exe"
fi

# 4. The Wine prefix (no Mono or Gecko prompts).
export WINEPREFIX=$dir/prefix WINEDEBUG=-all
if [ ! -f "$WINEPREFIX/system.reg" ]; then
    echo "creating the Wine prefix $WINEPREFIX ..." >&2
    WINEDLLOVERRIDES="mscoree,mshtml=" wine wineboot -i >/dev/null 2>&1 || true
    wineserver -w 2>/dev/null || true
    [ -f "$WINEPREFIX/system.reg" ] || fail "wineboot made no prefix in $WINEPREFIX"
fi
echo "oracle ready in $dir (d3dcompiler_47.dll sha256 ${DLL_SHA256:0:16}...)"
