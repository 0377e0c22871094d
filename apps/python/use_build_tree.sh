#!/usr/bin/env bash
# Makes the system Python import tactus from a build tree: writes tactus.pth, naming the build's
# python/ folder, into the user's site-packages (`python3 -m site --user-site`, created if
# missing). `make build` runs it; `cmake --install` is the other way to a importable module.
# Usage: use_build_tree.sh PYTHON BUILD/python
set -euo pipefail
python=$1
module_dir=$(cd "$2" && pwd)
site=$("$python" -m site --user-site)
mkdir -p "$site"
printf '%s\n' "$module_dir" > "$site/tactus.pth.tmp-$$"
mv "$site/tactus.pth.tmp-$$" "$site/tactus.pth"
echo "tactus Python module: $site/tactus.pth -> $module_dir" >&2
