"""README.md is the front door: at most 250 lines, and every relative link in it (and in the
documents it leads to: docs/*.md, models/*/README.md) points to a file that exists, and to a
heading that exists when the link names one (#anchor, GitHub's heading slugs).

Usage: readme_test.py [ignored...]  (run by CTest as python.readme)
"""

import pathlib
import re
import sys
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
MAX_README_LINES = 250

# [text](target) and ![alt](target); the target ends at whitespace or ')'.
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def code_free(text):
    """The text without fenced code blocks and inline code, where brackets are not links."""
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    return re.sub(r"`[^`\n]*`", "", text)


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = heading.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path):
    text = re.sub(r"```.*?```", "", path.read_text(encoding="utf-8"), flags=re.S)
    return {slug(m.group(1)) for m in re.finditer(r"^#+\s+(.*)$", text, flags=re.M)}


def broken_links(path, text=None):
    """Links of the file `path` (its text, or `text` as if it were there) that lead nowhere."""
    if text is None:
        text = path.read_text(encoding="utf-8")
    problems = []
    for target in LINK.findall(code_free(text)):
        if re.match(r"^[a-z]+:", target):  # http:, https:, mailto:
            continue
        file_part, _, anchor = target.partition("#")
        linked = (path.parent / file_part).resolve() if file_part else path
        if not linked.exists():
            problems.append(f"{path.name}: {target}: no such file")
        elif anchor and linked.suffix == ".md" and anchor not in anchors(linked):
            problems.append(f"{path.name}: {target}: no heading #{anchor}")
    return problems


class ReadmeTest(unittest.TestCase):
    def test_readme_is_short(self):
        lines = (ROOT / "README.md").read_text(encoding="utf-8").count("\n")
        self.assertLessEqual(lines, MAX_README_LINES)

    def test_readme_links_resolve(self):
        readme = ROOT / "README.md"
        self.assertGreater(len(LINK.findall(code_free(readme.read_text(encoding="utf-8")))), 10)
        self.assertEqual(broken_links(readme), [])

    def test_linked_documents_links_resolve(self):
        documents = sorted((ROOT / "docs").glob("*.md")) + sorted((ROOT / "models").glob("*/README.md"))
        problems = [p for document in documents for p in broken_links(document)]
        self.assertEqual(problems, [])

    def test_checker_finds_broken_links(self):
        # The checker itself must be able to fail.
        sample = "[a](README.md) [b](no/such/file.md) [c](README.md#no-such-heading)\n" \
                 "`[d](inline/code.md)` [e](README.md#where-things-are)\n"
        problems = broken_links(ROOT / "sample.md", sample)
        self.assertEqual(len(problems), 2, problems)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
