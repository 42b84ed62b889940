#!/usr/bin/env bash
# The Python package as users install it (docs/python.md), from a copy of this checkout's files
# (as a fresh clone): the README's commands (docs/examples/install_python.sh: a fresh virtual
# environment with --system-site-packages, `pip install --no-build-isolation .`), then the whole
# pytest suite against the installed package (not the build tree), `pip show`, the metadata,
# the README's Python example; `pip wheel .` and that wheel installed into a second virtual
# environment elsewhere; the user site (--user); `pip uninstall`. Offline: nothing is downloaded.
# Usage: bash tools/test_pip_install.sh [WORK_DIR]   (default build-pip-test/; tools/test.sh runs it)
# Environment: PYTHON (default: the python3 with NumPy that CMake picks: /usr/bin/python3 on
# Debian), EXACTCCD_CLI (the built exactccd, for the tests comparing with it; default build/exactccd),
# EXACTCCD_FALLING_CLOTH_CPP (the C++ simulation example that test_soak.py runs; default
# build/tests/example_falling_cloth).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
work=$(realpath -m "${1:-build-pip-test}")
python=${PYTHON:-}
if [ -z "$python" ]; then
  for candidate in "$(command -v python3 || true)" /usr/bin/python3; do
    if [ -n "$candidate" ] && "$candidate" -c "import numpy" 2>/dev/null; then python=$candidate; break; fi
  done
fi
[ -n "$python" ] || { echo "test_pip_install: no python3 with NumPy"; exit 1; }
export PATH="$(dirname "$python"):$PATH"   # the README's `python3` is this one
export PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1 PYTHONDONTWRITEBYTECODE=1 MPLBACKEND=Agg
export EXACTCCD_CLI=${EXACTCCD_CLI:-$root/build/exactccd}
export EXACTCCD_FALLING_CLOTH_CPP=${EXACTCCD_FALLING_CLOTH_CPP:-$root/build/tests/example_falling_cloth}
step() { echo "== [${SECONDS} s] test_pip_install: $*"; }

step "a copy of the checkout's files in $work/src"
rm -rf "$work"
mkdir -p "$work/src"
git ls-files -z --cached --others --exclude-standard | tar --null --ignore-failed-read -T - -cf - | tar -xf - -C "$work/src"

step "the README's install commands (docs/examples/install_python.sh)"
cd "$work/src"
bash -euo pipefail docs/examples/install_python.sh
. .venv/bin/activate
site=$(python -c "import sysconfig; print(sysconfig.get_paths()['platlib'])")
pip show exactccd
python -c "import importlib.metadata as m, exactccd; assert m.version('exactccd') == exactccd.__version__"

step "pytest against the installed package"
cd "$work"   # not a source tree: exactccd is imported from the virtual environment
EXACTCCD_EXPECT_INSTALLED="$site" EXACTCCD_DATA="$root/data" EXACTCCD_TEST_DATA="$root/tests/data" \
  python -m pytest -q -p no:cacheprovider "$root/python/tests"
(cd "$work/src" && python docs/examples/first_query.py > "$work/example.txt")
head -2 "$work/example.txt"

step "pip wheel . and the wheel installed into another virtual environment"
(cd "$work/src" && pip wheel --no-build-isolation --no-deps -w "$work/dist" . > "$work/wheel.log")
wheel=$(ls "$work"/dist/exactccd-*.whl)
echo "$wheel"
deactivate
"$python" -m venv --system-site-packages "$work/elsewhere"
"$work/elsewhere/bin/pip" install "$wheel" > "$work/elsewhere.log"
(cd / && "$work/elsewhere/bin/python" -c "import exactccd, numpy; \
assert exactccd.__file__.startswith('$work/elsewhere/'), exactccd.__file__; \
assert exactccd.point_point_toi(numpy.array([[[0, 0, 0], [2, 0, 0], [0, 0, 0], [0, 0, 0]]]), min_distance=0.5).tolist() == [[0.75, 0.75]]; \
print('wheel imports from', exactccd.__file__)")

step "the user site (pip install --user)"
export PYTHONUSERBASE="$work/userbase"
# Debian marks its interpreter externally managed (PEP 668): a --user install needs
# --break-system-packages (docs/python.md).
(cd "$work/src" && "$python" -m pip install --user --no-build-isolation --break-system-packages . > "$work/user.log")
(cd / && "$python" -c "import exactccd; assert exactccd.__file__.startswith('$work/userbase/'), exactccd.__file__; print('user site:', exactccd.__file__)")
"$python" -m pip uninstall -y --break-system-packages exactccd
if (cd / && "$python" -c "import exactccd" 2>/dev/null); then echo "still importable after pip uninstall (user site)"; exit 1; fi
unset PYTHONUSERBASE

step "pip uninstall"
. "$work/src/.venv/bin/activate"
pip uninstall -y exactccd
if (cd / && python -c "import exactccd" 2>/dev/null); then echo "still importable after pip uninstall"; exit 1; fi
if ls "$site"/exactccd* >/dev/null 2>&1; then echo "files left after pip uninstall: $(ls -d "$site"/exactccd*)"; exit 1; fi
step "done"
