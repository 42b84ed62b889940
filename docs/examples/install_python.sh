python3 -m venv --system-site-packages .venv && . .venv/bin/activate   # or --user: docs/python.md
pip install --no-build-isolation .    # offline: Debian's setuptools, wheel, pybind11, NumPy
python -c "import exactccd; print(exactccd.__version__)"
