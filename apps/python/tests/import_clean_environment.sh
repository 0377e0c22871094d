#!/usr/bin/env bash
# The system Python imports tactus with nothing in its environment but a home, once
# use_build_tree.sh has run (as `make build` runs it), and not before. The home is a temporary
# one, so the user's own site-packages is left alone.
# Installed with `cmake --install` into a prefix, the package imports from the prefix's
# platlib and finds the presets installed beside it.
# Usage: import_clean_environment.sh PYTHON BUILD/python use_build_tree.sh BUILD PLATLIB_IN_PREFIX
set -euo pipefail
python=$1 module_dir=$(cd "$2" && pwd) link=$3 build=$4 platlib=$5
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
check='import tactus, numpy; print(tactus.__file__); y = tactus.render(numpy.zeros(4800, numpy.float32), 48000); assert y.shape[0] >= 4800 and y.shape[1] == 1 and not y.any()'
if env -i HOME="$home" "$python" -c "$check" 2>/dev/null; then
  echo "FAIL: tactus imports before use_build_tree.sh ran" >&2
  exit 1
fi
HOME="$home" bash "$link" "$python" "$module_dir"
file=$(env -i HOME="$home" "$python" -c "$check")
case "$file" in
  "$module_dir"/tactus/__init__.py) echo "imported $file" ;;
  *) echo "FAIL: imported $file, not the build tree's" >&2; exit 1 ;;
esac

prefix="$home/prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
presets=$(env -i HOME="$home/nobody" PYTHONPATH="$prefix/$platlib" "$python" -c \
  'import tactus; print(tactus.__file__, *sorted(p["path"] for p in tactus.presets()))')
expected="$prefix/$platlib/tactus/__init__.py"
for shipped in "$build"/share/tactus/presets/*.toml; do
  expected+=" $prefix/share/tactus/presets/$(basename "$shipped")"
done
if [ "$presets" != "$expected" ]; then
  echo "FAIL: installed: $presets" >&2
  exit 1
fi
echo "installed: $presets"
