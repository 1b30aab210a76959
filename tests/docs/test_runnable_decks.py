"""Every deck shown in the README and docs/ that is marked runnable runs to its end.

A Markdown deck block is marked by the line `<!-- runnable -->` right before its fence; the
marker may give variables for a short version of a long deck, which override the deck's
`index` variables: `<!-- runnable: n_layers=2 t_relax=1 -->`. Each deck runs from an empty
folder with `-var root <repository>`, so a deck may read files as ${root}/examples/...
"""

import os
import re

from liggghts_run import SOURCE, DeckTestCase, main, run
from test_docs import markdown_files

MARKER = re.compile(r"^<!-- runnable(?::\s*(.*?))?\s*-->\s*\n```[^\n]*\n(.*?)^```", re.M | re.S)


def runnable_blocks():
    """[(page relative to the repository, line, variables, deck text)]."""
    blocks = []
    for path in markdown_files():
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for m in MARKER.finditer(text):
            variables = dict(word.split("=", 1) for word in (m.group(1) or "").split())
            line = text.count("\n", 0, m.start()) + 1
            blocks.append((os.path.relpath(path, SOURCE), line, variables, m.group(2)))
    return blocks


class RunnableDecks(DeckTestCase):
    def test_marked_decks_run(self):
        blocks = runnable_blocks()
        pages = {page for page, _, _, _ in blocks}
        self.assertIn("README.md", pages, "the README's first deck is marked runnable")
        self.assertIn("docs/tutorial.md", pages)
        for page, line, variables, deck in blocks:
            with self.subTest(page=page, line=line):
                self.assertRanCleanly(run(deck, variables=dict(variables, root=SOURCE)))

    def test_the_marker_reader(self):
        page = "x\n<!-- runnable: a=1 b=two -->\n```\nunits lj\n```\n\n```\nnot marked\n```\n"
        found = [(m.group(1), m.group(2)) for m in MARKER.finditer(page)]
        self.assertEqual(found, [("a=1 b=two", "units lj\n")])


if __name__ == "__main__":
    main()
