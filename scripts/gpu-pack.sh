#!/usr/bin/env bash
# Packs the release build's programs for a lent GPU machine, whose image
# has none of Debian's packages (docs/benchmarks.md, "Measuring on a lent
# GPU"): the benches and the app stripped, at the build-tree paths they
# were built with, the mock OpenXR runtime, every shared library they and
# Xvfb load (glibc and the C++ runtime excepted: the machine's are newer),
# Xvfb with xkbcomp and its keyboard data, and Mesa's software driver for
# Xvfb's own GLX. One xz file, .gpu/pack.tar.xz, ignored by git; carry
# `.gpu` and run scripts/gpu-measure.sh there.
#
# Usage: bash scripts/gpu-pack.sh [BUILD_DIR]   (default build/release, built)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build/release}" && pwd)
case "$build" in "$root"/*) ;; *) echo "gpu-pack: $build is not inside $root" >&2; exit 2 ;; esac
rel=${build#"$root"/}
programs=(hypergarden-full bench/bench_garden bench/bench_xr bench/bench_look)
for p in "${programs[@]}" libhg_mock_openxr.so xr/hg_mock_openxr.json; do
  [ -e "$build/$p" ] || { echo "gpu-pack: $build/$p is missing: build the release preset first" >&2; exit 2; }
done
for p in /usr/bin/Xvfb /usr/bin/xkbcomp /usr/share/X11/xkb /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so; do
  [ -e "$p" ] || { echo "gpu-pack: $p is missing: bash scripts/install-deps.sh installs it" >&2; exit 2; }
done

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/tree/$rel/bench" "$stage/tree/$rel/xr" "$stage/bin" "$stage/lib" "$stage/dri"
for p in "${programs[@]}" libhg_mock_openxr.so; do strip -o "$stage/tree/$rel/$p" "$build/$p"; done
cp "$build/xr/hg_mock_openxr.json" "$stage/tree/$rel/xr/"
cp /usr/bin/Xvfb /usr/bin/xkbcomp "$stage/bin/"
cp -rL /usr/share/X11/xkb "$stage/xkb"
cp -L /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so "$stage/dri/"
# The programs' own paths (content/, the mock runtime's manifest) were
# compiled in: gpu-measure.sh links this root to the checkout there.
echo "$root" > "$stage/source-dir"

# glibc and the C++ runtime stay the machine's (Ubuntu 24.04: newer, and
# backward compatible); libepoxy opens the GL libraries itself, so they
# are named here besides what ldd finds.
system='^(linux-vdso|ld-linux|libc|libm|libdl|libpthread|librt|libresolv|libutil|libstdc\+\+|libgcc_s)\.so'
elves=()
while IFS= read -r -d '' f; do elves+=("$f"); done < <(find "$stage/tree" "$stage/bin" "$stage/dri" -type f -perm -u+x -print0)
elves+=("$stage/dri/swrast_dri.so" "$stage/tree/$rel/libhg_mock_openxr.so")
for lib in libGL.so.1 libGLX.so.0 libGLdispatch.so.0 libGLX_mesa.so.0 libglapi.so.0 libEGL.so.1; do
  [ -e "/usr/lib/x86_64-linux-gnu/$lib" ] && cp -L "/usr/lib/x86_64-linux-gnu/$lib" "$stage/lib/"
done
# needs FILE: "name path" for each library FILE loads (path "not" when none
# is found), the pack's own copies first.
needs() { LD_LIBRARY_PATH="$stage/lib" ldd "$1" 2>/dev/null | awk '$2 == "=>" {print $1, $3}'; }
# The programs' needs and the libraries' own, until nothing new arrives.
while :; do
  before=$(ls "$stage/lib" | wc -l)
  for f in "${elves[@]}" "$stage"/lib/*; do needs "$f"; done | sort -u | while read -r name path; do
    [[ "$name" =~ $system ]] || [ -e "$stage/lib/$name" ] || [[ "$path" != /* ]] || cp -L "$path" "$stage/lib/$name"
  done
  [ "$(ls "$stage/lib" | wc -l)" = "$before" ] && break
done

# ICU's data (31 MB, 7.5 MB packed) comes in only because Mesa's LLVM
# links libxml2, which links ICU; nothing on this path converts text, so a
# library of the same name with an empty table stands in. Without it the
# pack and the checkout together pass the 64 MiB a lent machine takes.
if [ -e "$stage/lib/libicudata.so.72" ]; then
  printf 'const unsigned char icudt72_dat[32] = {0};\n' > "$stage/icudata.c"
  cc -shared -fPIC -Wl,-soname,libicudata.so.72 -o "$stage/lib/libicudata.so.72" "$stage/icudata.c"
  rm "$stage/icudata.c"
fi

# Every library each program needs resolves inside the pack, or is the
# machine's glibc or C++ runtime.
bad=0
for f in "${elves[@]}" "$stage"/lib/*; do
  while read -r name path; do
    [[ "$name" =~ $system ]] && continue
    case "$path" in "$stage"/lib/*) ;; *) echo "gpu-pack: $(basename "$f") needs $name from $path" >&2; bad=1 ;; esac
  done < <(needs "$f")
done
[ "$bad" = 0 ] || exit 1

mkdir -p "$root/.gpu"
tar -C "$stage" -cf - . | xz -T0 -9e > "$root/.gpu/pack.tar.xz"
echo "gpu-pack: $root/.gpu/pack.tar.xz, $(du -m "$root/.gpu/pack.tar.xz" | cut -f1) MiB ($(ls "$stage/lib" | wc -l) libraries)"
