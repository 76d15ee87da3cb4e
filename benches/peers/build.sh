#!/usr/bin/env bash
# Build the CGAL visibility peer: target/peers/cgal_visibility (from the repo
# root). Installs libcgal-dev, libgmp-dev and libmpfr-dev with apt-get when
# they are missing (sudo only when not root). Idempotent: recompiles only when
# the source is newer than the binary. Prints the binary's path.
#
#   benches/peers/build.sh            # release build (-O2 -DNDEBUG)
#   CGAL_PEER_DEBUG=1 benches/peers/build.sh
#                                     # also target/peers/cgal_visibility_debug,
#                                     # with CGAL's assertions on
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
src="$here/cgal_visibility.cpp"
outdir="$root/target/peers"
bin="$outdir/cgal_visibility"

missing=()
for pkg in libcgal-dev libgmp-dev libmpfr-dev; do
  if ! dpkg -s "$pkg" >/dev/null 2>&1; then
    missing+=("$pkg")
  fi
done
if ! command -v g++ >/dev/null 2>&1; then
  missing+=(g++)
fi
if [ "${#missing[@]}" -gt 0 ]; then
  if [ "$(id -u)" -eq 0 ]; then
    sudo=()
  else
    sudo=(sudo)
  fi
  echo "installing: ${missing[*]}" >&2
  "${sudo[@]}" apt-get update >&2
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y "${missing[@]}" >&2
fi

mkdir -p "$outdir"
flags=(-std=c++17 -Wall -Wextra)
libs=(-lmpfr -lgmp)
if [ ! -x "$bin" ] || [ "$src" -nt "$bin" ] || [ "$0" -nt "$bin" ]; then
  echo "compiling $bin" >&2
  g++ -O2 -DNDEBUG "${flags[@]}" -o "$bin.tmp" "$src" "${libs[@]}"
  mv "$bin.tmp" "$bin"
fi
if [ -n "${CGAL_PEER_DEBUG:-}" ]; then
  dbg="$outdir/cgal_visibility_debug"
  if [ ! -x "$dbg" ] || [ "$src" -nt "$dbg" ]; then
    echo "compiling $dbg" >&2
    g++ -O1 -g "${flags[@]}" -o "$dbg.tmp" "$src" "${libs[@]}"
    mv "$dbg.tmp" "$dbg"
  fi
fi
echo "$bin"
