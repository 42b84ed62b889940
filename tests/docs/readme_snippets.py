"""README.md cannot drift from the code: every fenced block of README.md is preceded by a line
`<!-- snippet: PATH -->` and equals the file PATH (under docs/examples/), which tests run (the
C++ example compiled and run, the Python example and the command lines executed, the Python
install by tools/test_pip_install.sh; tests/CMakeLists.txt), and every command of
docs/examples/two_commands.sh is a line of .ci/run. Also: the README is at most 150 lines, and
every file directly in docs/examples/ is shown in it (docs/examples/simulation/ holds the longer
simulation example, shown in docs/simulation.md).

Usage: python3 tests/docs/readme_snippets.py SOURCE_DIR"""

import pathlib
import re
import sys


def main(root):
    readme = (root / "README.md").read_text(encoding="utf-8")
    lines = readme.split("\n")
    errors, shown = [], set()
    fence = re.compile(r"^```")
    i = 0
    while i < len(lines):
        if fence.match(lines[i]):
            start = i
            i += 1
            while i < len(lines) and not fence.match(lines[i]):
                i += 1
            body = "\n".join(lines[start + 1:i]) + "\n"
            before = next((lines[k] for k in range(start - 1, -1, -1) if lines[k].strip()), "")
            m = re.fullmatch(r"<!-- snippet: (\S+) -->", before.strip())
            if not m:
                errors.append(f"README.md:{start + 1}: a fenced block without a `<!-- snippet: PATH -->` line before it")
            else:
                path = root / m[1]
                shown.add(m[1])
                if not path.is_file():
                    errors.append(f"README.md:{start + 1}: {m[1]} does not exist")
                elif path.read_text(encoding="utf-8") != body:
                    errors.append(f"README.md:{start + 1}: the block differs from {m[1]} (copy the file into the README)")
        i += 1
    for path in sorted((root / "docs" / "examples").iterdir()):
        rel = path.relative_to(root).as_posix()
        if path.suffix in (".cpp", ".py", ".sh") and rel not in shown:
            errors.append(f"{rel} is not shown in README.md")
    ci = (root / ".ci" / "run").read_text(encoding="utf-8").split("\n")
    for command in (root / "docs" / "examples" / "two_commands.sh").read_text(encoding="utf-8").splitlines():
        command = command.split("#")[0].strip()
        if command and command not in (c.strip() for c in ci):
            errors.append(f"`{command}` (README, the two commands) is not run by .ci/run")
    if len(lines) > 151:
        errors.append(f"README.md has {len(lines) - 1} lines, more than 150")
    for e in errors:
        print(e)
    print(f"{len(shown)} snippets checked, {len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1])))
