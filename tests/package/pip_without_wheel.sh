#!/usr/bin/env bash
# `pip install --no-build-isolation .` with an interpreter whose setuptools cannot build a wheel
# (a virtual environment made without --system-site-packages: setuptools, but no `wheel`
# package) stops with setup.py's message naming the interpreter and the fix, not setuptools'
# `error: invalid command 'bdist_wheel'`. Offline; it stops before any compilation (seconds).
# Usage: bash tests/package/pip_without_wheel.sh PYTHON SOURCE_DIR WORK_DIR
set -euo pipefail
python=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work/src"
cp -r "$source"/{setup.py,setup.cfg,pyproject.toml,CMakeLists.txt,README.md,python} "$work/src/"
"$python" -m venv "$work/venv"
if "$work/venv/bin/python" -c "import wheel" 2>/dev/null; then
  echo "pip_without_wheel: the new virtual environment has the wheel package: nothing to test"; exit 1
fi
set +e
out=$(cd "$work/src" && PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1 "$work/venv/bin/pip" install --no-build-isolation . 2>&1)
rc=$?
set -e
echo "$out" | tail -12
fail() { echo "pip_without_wheel: $*"; exit 1; }
[ "$rc" -ne 0 ] || fail "pip install succeeded without the wheel package"
case "$out" in *"invalid command 'bdist_wheel'"*) fail "setuptools' bare error instead of the message" ;; esac
case "$out" in *"exactccd: $work/venv/bin/python"*"cannot build a wheel"*) ;; *) fail "no message naming the interpreter" ;; esac
case "$out" in *"apt-get install python3-wheel"*"--system-site-packages"*) ;; *) fail "the message does not give the fix" ;; esac
echo "pip_without_wheel: stopped with the message"
