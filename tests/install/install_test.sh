#!/bin/bash
# install_test.sh CMAKE BUILD BINDIR PLUGINDIR DATADIR [PYTHON PYTHONDIR]
# Installs BUILD into a temporary prefix, moves the prefix, and runs from it alone:
#  - only `ringvib` in bin/ (no test program installed);
#  - `ringvib --version` names the prefix's plug-in (never the build tree's);
#  - a tiny FE scene through the installed command (`modes ... --solver fem`);
#  - with PYTHON: the installed module (PYTHONPATH = the prefix's site-packages only) imports
#    from the prefix, computes the same FE frequencies as the command, and the plug-in it
#    mapped is the prefix's (/proc/self/maps); its type stubs ringvib.pyi lie beside it.
# Environments are emptied (env -i): no RINGVIB_FEM_MODULE, no LD_LIBRARY_PATH.
set -euo pipefail
cmake=$1 build=$2 bindir=$3 plugindir=$4 datadir=$5 python=${6:-} pythondir=${7:-}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/ringvib-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "install_test: $*" >&2; exit 1; }

"$cmake" --install "$build" --prefix "$tmp/installed" > "$tmp/install.log" || { cat "$tmp/install.log"; fail "cmake --install failed"; }
mv "$tmp/installed" "$tmp/moved"
P=$(cd "$tmp/moved" && pwd -P)
build=$(cd "$build" && pwd -P)
# run [VAR=value...] COMMAND...: in an empty environment with the prefix's bin/ alone on PATH.
run() { env -i HOME="$tmp" LANG=C.UTF-8 PATH="$P/$bindir" "$@"; }

[ "$(ls "$P/$bindir")" = ringvib ] || fail "$P/$bindir holds $(ls "$P/$bindir" | tr '\n' ' '), expected ringvib alone"
[ -f "$P/$plugindir/libringvib_fem.so" ] || fail "no plug-in at $P/$plugindir/libringvib_fem.so"

version=$(run ringvib --version)
echo "$version"
grep -qxF "FE plug-in: $P/$plugindir/libringvib_fem.so" <<< "$version" \
  || fail "ringvib --version names another plug-in than the prefix's"

scene=$P/$datadir/ringvib/scenes/paper1990.toml
args=(modes "$scene" --solver fem --set fem.elements=8 --set modes.count=3)
run ringvib "${args[@]}" --json > "$tmp/modes.json" || fail "installed ringvib ${args[*]} exited $?"
echo "ringvib ${args[*]}: $(wc -c < "$tmp/modes.json") bytes of JSON"

if [ -n "$python" ]; then
  [ -f "$P/$pythondir/ringvib.pyi" ] || fail "no type stubs at $P/$pythondir/ringvib.pyi"
  run PYTHONPATH="$P/$pythondir" PYTHONDONTWRITEBYTECODE=1 "$python" - "$P" "$build" "$scene" "$tmp/modes.json" <<'PY'
import json, sys
prefix, build, scene, command_json = sys.argv[1:]
import ringvib
assert ringvib.__file__.startswith(prefix + "/"), f"ringvib imported from {ringvib.__file__}, not from {prefix}"
s = ringvib.Scene.load(scene, set={"fem.elements": 8, "modes.count": 3})
m = ringvib.modes(s, "fem")
maps = [line.split()[-1] for line in open("/proc/self/maps") if line.rstrip().endswith("libringvib_fem.so")]
assert maps and all(p.startswith(prefix + "/") for p in maps), f"plug-in mapped from {sorted(set(maps))}"
assert not any(p.startswith(build + "/") for p in maps)
command = json.load(open(command_json))
assert len(m.omega) == 3 and m.omega.tolist() == command["omega"], f"{m.omega.tolist()} != {command['omega']}"
print("module:", ringvib.__file__, "| plug-in:", maps[0], "| omega:", list(m.omega))
PY
fi
echo "install_test: ok ($P)"
