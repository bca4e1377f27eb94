#!/usr/bin/env bash
# Makes `python3 -c "import matpredict"` work from any folder for the user running it: a
# matpredict.pth file in that user's site-packages names the build tree's package folder, as
# `pip install --user --editable` would, so a rebuild is seen at once and nothing is copied.
# `cmake --install` is the other way (a prefix's dist-packages). Undo with
#   rm "$(/usr/bin/python3 -m site --user-site)/matpredict.pth"
# Usage: register_python_package.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
package="$build/python"
python=$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt")
if [ -z "$python" ] || [ ! -f "$package/matpredict/__init__.py" ]; then
  echo "register_python_package: $build has no Python package (MATPREDICT_PYTHON is off); nothing registered" >&2
  exit 0
fi
if ! "$python" -c 'import site, sys; sys.exit(0 if site.ENABLE_USER_SITE else 1)'; then
  echo "register_python_package: $python has no user site-packages (a virtual environment?); use PYTHONPATH=$package" >&2
  exit 0
fi
site=$("$python" -m site --user-site)
mkdir -p "$site"
printf '%s\n' "$package" > "$site/matpredict.pth.partial"
mv "$site/matpredict.pth.partial" "$site/matpredict.pth"
# The check a user would make: from elsewhere, with no PYTHONPATH.
imported=$(cd / && env -u PYTHONPATH "$python" -c 'import matpredict; print(matpredict.__file__)')
case "$imported" in
  "$package"/*) echo "matpredict: $python imports $imported ($site/matpredict.pth)" ;;
  *) echo "register_python_package: $python imports matpredict from $imported, not $package (an installed copy first on its path?)" >&2
     exit 1 ;;
esac
