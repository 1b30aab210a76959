"""The documentation against the code.

- Every style the plugin registers (the *Style(name, Class) lines of src_plugin) has its page
  in docs/commands/, with the sections of a LIGGGHTS command page in their order.
- The keywords a page lists are the keywords the style accepts. The accepted set is read from
  the code through the binary: a probe deck gives the style an unknown keyword, and the
  message lists what the style accepts ("unknown keyword 'x'; accepted: a, b"); then each
  accepted keyword is given once without its value, to show that a branch handles it.
- No development history in tracked text (tests/tools/history_words.py), no citation of a
  file outside the repository, every relative link of the Markdown pages resolves, and the
  README stays short and reaches the command pages in one click.
"""

import concurrent.futures
import glob
import os
import re
import sys
import unittest

from liggghts_run import SOURCE, DeckTestCase, main, run

sys.path.insert(0, os.path.join(SOURCE, "tests", "tools"))
import history_words  # noqa: E402

DOCS = os.path.join(SOURCE, "docs")
COMMANDS = os.path.join(DOCS, "commands")
SECTIONS = ["Syntax", "Examples", "Description", "Output", "Restart", "Restrictions", "Related commands",
            "Default"]
NO_KEYWORDS = "This style takes no keywords."

# The style registrations of LIGGGHTS' style headers: FixStyle(wire/grain,FixWireGrain)
REGISTRATION = re.compile(r"^(AtomStyle|CommandStyle|ComputeStyle|DumpStyle|FixStyle|PairStyle)\(([^,]+),(\w+)\)",
                          re.M)
PAGE_PREFIX = {"AtomStyle": "atom_style_", "CommandStyle": "", "ComputeStyle": "compute_", "DumpStyle": "dump_",
               "FixStyle": "fix_", "PairStyle": "pair_style_"}


def registered_styles():
    """[(macro, style name, header path)] of every style in src_plugin."""
    found = []
    for header in sorted(glob.glob(os.path.join(SOURCE, "src_plugin", "*", "*.h"))):
        with open(header, encoding="utf-8") as f:
            for macro, name, _ in REGISTRATION.findall(f.read()):
                found.append((macro, name, header))
    return found


def page_name(macro, name):
    return PAGE_PREFIX[macro] + name.replace("/", "_") + ".md"


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def keyword_tables(text):
    """{first header cell: set of keywords} of the Markdown tables whose first header cell is
    'keyword' or '<sub-command> keyword'; a keyword is the backticked word of a row's first cell."""
    tables = {}
    lines = text.splitlines()
    for k, line in enumerate(lines):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if not line.lstrip().startswith("|") or not cells or not cells[0].endswith("keyword"):
            continue
        if k + 1 >= len(lines) or not re.match(r"^\s*\|[\s:|-]+\|\s*$", lines[k + 1]):
            continue
        names = set()
        for row in lines[k + 2:]:
            if not row.lstrip().startswith("|"):
                break
            first = row.strip().strip("|").split("|")[0]
            names.update(re.findall(r"`([^`]+)`", first))
        tables[cells[0]] = names
    return tables


# Decks that end with the style's line (or its sub-command's) missing only its keywords: probe(word)
# appends `word` where the keywords go. Each gives the table of the page it is checked against.
def _head(style):
    return f"units lj\natom_style {style}\natom_modify map array sort 0 0.0\nboundary f f f\n"


def _box(style, xy, z, types):
    return _head(style) + (f"region box block -{xy} {xy} -{xy} {xy} {z[0]} {z[1]}\n"
                           f"create_box {types} box\n")


_WIRE = _box("wire", 2, (-2, 2), 2) + "create_wire 1 line 0 0 0 1 0 0\n"
_CUBE = _box("polyhedron", 6, (-6, 6), 1) + "create_grains 1 1 random box seed 5 shape cube 1 sweep 0\n"
_HYBRID = _box("hybrid polyhedron wire", 4, (-1, 6), 2) + (
    "create_grains 1 1 random box seed 3 shape cube 1 sweep 0.1\n"
    "create_wire 2 line -0.5 0.2 3.3 0.5 0.2 3.3 segment 0.5 radius 0.1\n"
    "group grains type 1\ngroup wire type 2\n")

PROBES = {
    # page: {table: deck prefix to which the probed word is appended}
    "atom_style_polyhedron.md": {"keyword": "units lj\natom_style polyhedron"},
    "atom_style_wire.md": {"keyword": "units lj\natom_style wire"},
    "create_wire.md": {"keyword": _box("wire", 2, (-2, 2), 2) + "create_wire 1 line 0 0 0 1 0 0"},
    "create_grains.md": {"keyword": _box("polyhedron", 6, (-6, 6), 1) + "create_grains 1 1 random box"},
    "fix_wire_elastic.md": {"keyword": _WIRE + "fix el all wire/elastic"},
    "compute_wire_energy.md": {"keyword": _WIRE + "compute e all wire/energy"},
    "pair_style_wire_contact.md": {"keyword": _WIRE + "pair_style wire/contact",
                                   "pair_coeff keyword": _WIRE + "pair_style wire/contact\npair_coeff * *"},
    "fix_wire_wall.md": {"keyword": _WIRE + "fix w all wire/wall plane 0 0 -1 0 0 1"},
    "compute_wire_contacts.md": {"keyword": _WIRE + "compute c all wire/contacts"},
    "fix_nve_gear.md": {"keyword": _WIRE + "fix g all nve/gear"},
    "fix_wire_contact_history.md": {"keyword": _WIRE + "fix h all wire/contact/history"},
    "dump_wire_vtk.md": {"keyword": _WIRE + "dump d all wire/vtk 10 w_*.vtp"},
    "fix_nve_polyhedron.md": {"keyword": _CUBE + "fix n all nve/polyhedron"},
    "fix_nscd_polyhedra.md": {"keyword": _CUBE + "fix n all nscd/polyhedra"},
    "compute_grain_rotation.md": {"keyword": _CUBE + "compute r all grain/rotation"},
    "compute_grain_shape.md": {"keyword": _CUBE + "compute s all grain/shape"},
    "dump_polyhedron_vtk.md": {"keyword": _CUBE + "dump d all polyhedron/vtk 10 p_*.vtp"},
    "fix_wire_grain.md": {"keyword": _HYBRID + "fix wg wire wire/grain grains"},
    "compute_column_height.md": {"keyword": _CUBE + "compute h all column/height"},
    "compute_column_retention.md": {"keyword": _CUBE + "compute r all column/retention radius 1"},
    "compute_contact_local.md": {"keyword": _CUBE + "compute c all contact/local"},
    "compute_grain_stress.md": {"keyword": _CUBE + "compute s all grain/stress"},
}
# Commands that read positional arguments only (no keyword loop: checked in their source).
POSITIONAL_ONLY = {"grain_shapes.md": "src_plugin/grains/grain_shapes.cpp",
                   "deck_error.md": "src_plugin/common/deck_error.cpp"}

UNKNOWN = "no_such_keyword"
ACCEPTED = re.compile(r"unknown keyword '" + UNKNOWN + r"'; (?:accepted: (.*?)|this style takes no keywords)"
                      r"(?: \([^()]*:\d+\))?$")


def accepted_keywords(prefix):
    """The keywords the code accepts where `prefix` ends, read from its message; None when the
    deck did not stop with the unknown-keyword message."""
    result = run(prefix + " " + UNKNOWN + "\n")
    for line in result.errors():
        m = ACCEPTED.search(line)
        if m:
            return set(m.group(1).split(", ")) if m.group(1) else set(), result
    return None, result


class CommandPages(DeckTestCase):
    def test_every_registered_style_has_its_page_with_the_sections_in_order(self):
        styles = registered_styles()
        self.assertGreaterEqual(len(styles), 20)
        for macro, name, header in styles:
            page = os.path.join(COMMANDS, page_name(macro, name))
            with self.subTest(style=name, page=page):
                self.assertTrue(os.path.isfile(page), f"{name} ({os.path.relpath(header, SOURCE)}) has no page")
                headings = re.findall(r"^## (.+?)\s*$", read(page), re.M)
                self.assertEqual([h for h in headings if h in SECTIONS], SECTIONS)
                self.assertTrue(read(page).startswith("# "), "the page opens with its title")

    def test_every_page_is_probed_or_positional_only(self):
        pages = {page_name(m, n) for m, n, _ in registered_styles()}
        self.assertEqual(pages, set(PROBES) | set(POSITIONAL_ONLY))

    def test_positional_only_commands_have_no_keywords(self):
        for page, source in POSITIONAL_ONLY.items():
            with self.subTest(page=page):
                self.assertNotIn("next_keyword(", read(os.path.join(SOURCE, source)))
                text = read(os.path.join(COMMANDS, page))
                self.assertEqual(keyword_tables(text), {})
                self.assertIn(NO_KEYWORDS, text)

    def test_keywords_of_each_page_are_those_the_code_accepts(self):
        jobs = [(page, table, prefix) for page, tables in sorted(PROBES.items()) for table, prefix in tables.items()]
        with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
            results = list(pool.map(lambda job: accepted_keywords(job[2]), jobs))
        for (page, table, prefix), (accepted, result) in zip(jobs, results):
            with self.subTest(page=page, table=table):
                self.assertNoSanitizerReport(result)
                self.assertIsNotNone(accepted, f"the probe did not reach the keywords: {result.errors()}\n"
                                     + result.output[-1500:])
                text = read(os.path.join(COMMANDS, page))
                listed = keyword_tables(text).get(table)
                if not accepted and table == "keyword":
                    self.assertIsNone(listed, "a style without keywords has no keyword table")
                    self.assertIn(NO_KEYWORDS, text)
                    continue
                self.assertIsNotNone(listed, f"{page} has no table headed '| {table} | values | default | meaning |'")
                self.assertEqual(sorted(listed - accepted), [], "listed on the page, refused by the code")
                self.assertEqual(sorted(accepted - listed), [], "accepted by the code, missing on the page")

    def test_each_accepted_keyword_is_handled(self):
        """Each keyword given without its value reaches a branch of the style's dispatch: the run
        stops with another message than the unknown or unhandled keyword (or runs)."""
        jobs = []
        for page, tables in sorted(PROBES.items()):
            for table, prefix in tables.items():
                accepted, _ = accepted_keywords(prefix)
                jobs += [(page, keyword, prefix) for keyword in sorted(accepted or ())]
        self.assertGreater(len(jobs), 60)
        with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
            results = list(pool.map(lambda job: run(job[2] + " " + job[1] + "\n"), jobs))
        for (page, keyword, _), result in zip(jobs, results):
            with self.subTest(page=page, keyword=keyword):
                self.assertNoSanitizerReport(result)
                for line in result.errors():
                    self.assertNotIn("unknown keyword", line)
                    self.assertNotIn("accepted but not handled", line)
                for crash in ("Segmentation fault", "Aborted", "core dumped"):
                    self.assertNotIn(crash, result.output)


class KeywordTables(unittest.TestCase):
    """The table reader itself, on a page made here."""

    def test_reads_the_keyword_tables_by_their_first_header_cell(self):
        page = ("| keyword | values | default | meaning |\n|---|---|---|---|\n| `a` | x | 1 | m |\n"
                "| `b_c` | x y | 2 | m |\n\ntext\n\n| fix_modify keyword | values | default | meaning |\n"
                "|---|---|---|---|\n| `v` | 3 numbers | 0 0 0 | m |\n\n| quantity | meaning |\n|---|---|\n"
                "| `f_ID[1]` | m |\n")
        self.assertEqual(keyword_tables(page), {"keyword": {"a", "b_c"}, "fix_modify keyword": {"v"}})


def markdown_files():
    """The tracked Markdown pages."""
    return [os.path.join(SOURCE, rel) for rel in history_words.tracked_files(SOURCE) if rel.endswith(".md")]


class Pages(unittest.TestCase):
    def test_no_development_history_in_tracked_files(self):
        found = history_words.findings(SOURCE)
        self.assertEqual(found, [], "history words in tracked files:\n" + "\n".join(found[:40]))

    def test_nothing_cites_a_file_outside_the_repository(self):
        found = []
        for rel in history_words.tracked_files(SOURCE):
            path = os.path.join(SOURCE, rel)
            if rel == "tests/docs/test_docs.py" or not os.path.isfile(path):
                continue
            with open(path, "rb") as f:
                data = f.read()
            if b"\0" in data[:8192]:
                continue
            for number, line in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
                if re.search(r"\.\./shared|\bDESIGN\.md\b", line):
                    found.append(f"{rel}:{number}: {line.strip()[:120]}")
        self.assertEqual(found, [])

    def test_relative_links_resolve(self):
        broken = []
        for path in markdown_files():
            text = read(path)
            text = re.sub(r"```.*?```", "", text, flags=re.S)   # not inside code blocks
            for target in re.findall(r"\]\(([^)\s]+)\)", text):
                if re.match(r"[a-z]+:", target) or target.startswith("#"):
                    continue
                file_part = target.split("#")[0]
                if not os.path.exists(os.path.normpath(os.path.join(os.path.dirname(path), file_part))):
                    broken.append(f"{os.path.relpath(path, SOURCE)}: {target}")
        self.assertEqual(broken, [])

    def test_readme_is_short_and_reaches_every_command_page(self):
        text = read(os.path.join(SOURCE, "README.md"))
        self.assertLessEqual(len(text.splitlines()), 200)
        links = set(re.findall(r"\]\((docs/commands/[^)#]+)", text))
        pages = {"docs/commands/" + page_name(m, n) for m, n, _ in registered_styles()}
        self.assertEqual(sorted(pages - links), [], "styles the README's table does not link")


if __name__ == "__main__":
    main()
