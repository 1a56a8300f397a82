#!/usr/bin/env python3
"""Every chapter page holds at most 1,500 words of prose, and the count is the one defined here.

    prose_words_test.py REPO_ROOT        (or: prose_words_test.py REPO_ROOT --report)

What counts as prose (the words a student reads as sentences):
- every line outside fenced code blocks (```), display maths ($$ ... $$, over several lines
  too), tables (lines that start with `|`) and HTML comments (the numbers' tags);
- headings, captions, lists and block quotes count;
- the page's last section, `## Reference: flags and outputs` (flag lists, output files,
  assignment markers, engine notes: what a student looks up rather than reads), is counted
  apart, against a limit of its own, REFERENCE_LIMIT, so that it cannot hide a lesson; nothing
  may follow it;
- a word is a whitespace-separated token holding a letter or a digit; an inline maths span
  ($...$) or an inline code span (`...`) counts as one word, as it is read as one; a link counts
  the words of its text, not its address; an image (![...](...)) counts nothing, its caption
  is the italic line below it, which counts.
A tagged number (0.0913<!--n:...-->) is one word: the tag is a comment and falls away.
"""

import os
import re
import sys
import unittest

REPO = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()
REPORT = "--report" in sys.argv
if REPORT:
    sys.argv.remove("--report")

# The limit of issue 35: a page a student reads in one sitting beside its program.
LIMIT = 1500
# The reference section holds lists to look things up in; a few hundred words hold any
# chapter's flags and outputs, and more would be a second lesson out of the count.
REFERENCE_LIMIT = 400
REFERENCE = "## Reference: flags and outputs"
CHAPTER_PAGE = re.compile(r"^\d\d_.*\.md$")

COMMENT = re.compile(r"<!--.*?-->", re.S)
DISPLAY_MATH = re.compile(r"\$\$.*?\$\$", re.S)
INLINE_MATH = re.compile(r"(?<![\\$])\$(?!\$)[^$\n]+?\$")
INLINE_CODE = re.compile(r"`[^`\n]+`")
IMAGE = re.compile(r"!\[[^\]]*\]\([^)]*\)")
LINK = re.compile(r"\[([^\]]*)\]\([^)]*\)")
WORD = re.compile(r"[A-Za-z0-9]")


def prose_words(text):
    """The number of prose words in a markdown page, as the module's docstring defines it."""
    kept, fenced = [], False
    for line in text.split("\n"):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if fenced or line.lstrip().startswith("|"):
            continue
        kept.append(line)
    text = "\n".join(kept)
    text = COMMENT.sub(" ", text)
    text = DISPLAY_MATH.sub(" ", text)
    text = INLINE_MATH.sub(" x ", text)
    text = INLINE_CODE.sub(" x ", text)
    text = IMAGE.sub(" ", text)
    text = LINK.sub(r" \1 ", text)
    return sum(1 for token in text.split() if WORD.search(token))


def split_reference(text):
    """(the lesson, the reference section or "") of a page."""
    at = text.find("\n" + REFERENCE + "\n")
    return (text, "") if at < 0 else (text[:at + 1], text[at + 1:])


def chapter_pages():
    folder = os.path.join(REPO, "docs")
    return sorted(name for name in os.listdir(folder) if CHAPTER_PAGE.match(name))


def read(name):
    with open(os.path.join(REPO, "docs", name), encoding="utf-8") as file:
        return file.read()


class ThePagesTest(unittest.TestCase):
    def test_there_are_nine_chapter_pages(self):
        self.assertEqual(len(chapter_pages()), 9, chapter_pages())

    def test_every_chapter_page_is_at_most_the_limit(self):
        over = []
        for name in chapter_pages():
            lesson, reference = split_reference(read(name))
            if prose_words(lesson) > LIMIT:
                over.append(f"{name}: {prose_words(lesson)} prose words (limit {LIMIT})")
            if prose_words(reference) > REFERENCE_LIMIT:
                over.append(f"{name}: {prose_words(reference)} words in its reference section "
                            f"(limit {REFERENCE_LIMIT})")
        self.assertEqual(over, [], "\n" + "\n".join(over))

    def test_the_reference_section_is_the_last(self):
        late = [name for name in chapter_pages()
                if "\n## " in split_reference(read(name))[1][len(REFERENCE):]]
        self.assertEqual(late, [], "a section follows the reference section")


class TheCountTest(unittest.TestCase):
    def test_plain_words_count(self):
        self.assertEqual(prose_words("# A title\n\nOne two, three.\n- four (five)"), 7)

    def test_code_tables_display_maths_and_comments_do_not_count(self):
        text = "\n".join([
            "word", "```sh", "build/bin/ch01 --spp 4 # many words here", "```",
            "| a | table | row |", "$$L = L_e +", "T L$$", "<!-- a comment of words -->",
            "$$x$$ after"])
        self.assertEqual(prose_words(text), 2)

    def test_inline_maths_code_and_tagged_numbers_are_one_word_each(self):
        text = "the error $c\\,h^2 = c/(n-1)^2$ of `trapezoid(f, segment, n)` is 0.0913<!--n:a.b-->"
        self.assertEqual(prose_words(text), 7)

    def test_links_count_their_text_and_images_nothing(self):
        text = "see [under the hood](under-the-hood.md#x) ![a long alt text](figures/x.png)"
        self.assertEqual(prose_words(text), 4)

    def test_a_page_over_the_limit_is_caught(self):
        self.assertGreater(prose_words("word " * (LIMIT + 1)), LIMIT)

    def test_the_reference_section_is_split_off_and_only_it(self):
        page = "# T\n\nlesson words\n\n" + REFERENCE + "\n\nflag list\n"
        lesson, reference = split_reference(page)
        self.assertEqual((prose_words(lesson), prose_words(reference)), (3, 6))
        self.assertEqual(split_reference("# T\n\nno reference\n")[1], "")


if __name__ == "__main__":
    if REPORT:
        for name in chapter_pages():
            lesson, reference = split_reference(read(name))
            print(f"{prose_words(lesson):5d} {prose_words(reference):4d}  {name}")
        sys.exit(0)
    unittest.main()
