#!/usr/bin/env python3
"""Every commit a document cites is on main (the history of HEAD).

A document is any Markdown file git tracks; a cited commit is a token of 7 to 40 lowercase
hexadecimal digits between backticks (`ebfed98`), as the documents write them. Each must be an
ancestor of HEAD (or HEAD), or a commit of a peer the documents measure against, listed in
PEER_COMMITS with the peer's name, which must then appear on the same line or the line before
(so that a peer's hash cannot stand for one of ours). Exits 1 listing every other citation,
0 when there is none, 77 (CTest's skip) when the tree has no git history to check against.

usage: cited_commits.py REPOSITORY_ROOT
"""
import pathlib
import re
import subprocess
import sys

# The peers' commits cited beside their figures (docs/performance.md, docs/fuzzing.md 2b, ...),
# each with a name the citing line (or the line before) must hold.
PEER_COMMITS = {
    "ca9a8c2": "Tight Inclusion",   # the side-by-side harness's peer
    "7377d78": "Tight Inclusion",   # v1.0.6, the version the IPC Toolkit's CMake recipe pins
    "8f9347c": "Scalable CCD",
    "b40e9c07": "IPC Toolkit",
}

CITATION = re.compile(r"`([0-9a-f]{7,40})`")


def git(root, *args):
    return subprocess.run(["git", "-C", str(root), *args], capture_output=True, text=True)


def on_main(root, commit):
    return git(root, "merge-base", "--is-ancestor", commit, "HEAD").returncode == 0


def names_peer(lines, number, peer):
    here = lines[number - 1]
    before = lines[number - 2] if number >= 2 else ""
    return peer.lower() in (before + " " + here).lower()


def violations(root):
    found = []
    documents = git(root, "ls-files", "*.md").stdout.split()
    for document in sorted(documents):
        lines = (root / document).read_text(encoding="utf-8").splitlines()
        for number, line in enumerate(lines, 1):
            for commit in CITATION.findall(line):
                peer = PEER_COMMITS.get(commit)
                if peer is not None:
                    if not names_peer(lines, number, peer):
                        found.append(f"{document}:{number}: `{commit}` is {peer}'s commit, but the line does not name {peer}")
                elif not on_main(root, commit):
                    found.append(f"{document}:{number}: `{commit}` is not a commit on main (nor a listed peer's)")
    return found


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = pathlib.Path(sys.argv[1])
    if git(root, "rev-parse", "--verify", "HEAD").returncode != 0:
        print(f"skipped: {root} has no git history (a source copy, not a clone)")
        return 77
    if git(root, "rev-parse", "--is-shallow-repository").stdout.strip() == "true":
        print(f"skipped: {root} is a shallow clone (the cited commits may be older than its history)")
        return 77
    found = violations(root)
    for v in found:
        print(v)
    if found:
        print(f"{len(found)} citation(s) of a commit that is not on main")
        return 1
    print("every commit the documents cite is on main or a named peer's")
    return 0


if __name__ == "__main__":
    sys.exit(main())
