#!/bin/bash
# deb_test.sh CPACK BUILD PLUGINDIR PYTHONDIR: builds the Debian package of BUILD with
# `cpack -G DEB` (packaging/CMakeLists.txt) into a temporary folder and checks what a new machine
# would get from `apt-get install ./ringvib_*.deb` without installing it (docs/development.md,
# "The Debian package"): its name, the program, the FE plug-in where the program looks for it,
# the Python module with its stubs, the scenes, and the packages it declares it needs.
set -euo pipefail
cpack=$1 build=$2 plugindir=$3 pythondir=${4:-}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/ringvib-deb.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "deb_test: $*" >&2; exit 1; }

"$cpack" -G DEB -B "$tmp" --config "$build/CPackConfig.cmake" > "$tmp/cpack.log" 2>&1 \
  || { cat "$tmp/cpack.log"; fail "cpack -G DEB failed"; }
debs=("$tmp"/ringvib_*_*.deb)
[ ${#debs[@]} = 1 ] && [ -f "${debs[0]}" ] || fail "expected one ringvib_<version>_<arch>.deb in $tmp, found: $(ls "$tmp")"
deb=${debs[0]}
echo "built $(basename "$deb"): $(du -k "$deb" | cut -f1) KiB"

dpkg-deb --contents "$deb" | awk '{print $NF}' > "$tmp/contents"
has() { grep -qxE "$1" "$tmp/contents" || fail "the package holds no $1"; }
has "\./usr/bin/ringvib"
has "\./usr/$plugindir/libringvib_fem\.so"
has "\./usr/share/ringvib/scenes/paper1990\.toml"
if [ -n "$pythondir" ]; then
  has "\./usr/$pythondir/ringvib\.cpython-[^/]*\.so"
  has "\./usr/$pythondir/ringvib\.pyi"
fi
if grep -qE "/(tests?|bin)/[a-z_]+_tests$" "$tmp/contents"; then fail "the package holds a test program"; fi

[ "$(dpkg-deb --field "$deb" Package)" = ringvib ] || fail "the package is not named ringvib"
depends=$(dpkg-deb --field "$deb" Depends)
echo "Depends: $depends"
for need in "libdeal\.ii" "gnuplot" ${pythondir:+"python3-numpy"}; do
  grep -qE "$need" <<< "$depends" || fail "Depends does not name $need: $depends"
done
echo "deb_test: the package holds the program, the plug-in, the module and the scenes, and declares deal.II"
