#!/usr/bin/env python3
"""The gallery page (scripts/make-gallery) and the docs pages rendered to HTML
(scripts/render-docs) opened in headless Chromium (issues #15 item 6, #35 section 4).

  gallery_test.py --tmp DIR --make-gallery PATH --chapter NAME=PATH ...

Runs each chapter given with tiny flags into DIR/out/, adds a folder whose file names and
summary.json need escaping, renders the docs pages into DIR/out/docs/ and runs make-gallery on
DIR/out/, then checks:
  - the gallery's source: every <img> and link relative (no scheme, no leading '/', no
    network), no external script, style or font, the chapters not run listed as "not run",
    the text taken from files escaped, every chapter's section linking to its rendered page
    (docs/NN_name.html, not the raw .md);
  - render-docs refuses an OUT/docs/ it did not write (exit 2, one line, the folder untouched);
    render-docs and make-gallery refuse a bad flag and an empty --out (exit 2, one line naming
    it, nothing written); stopped by SIGTERM (as scripts/run-chapters stops it when its
    build fails) it exits 143 and leaves nothing behind;
  - in Chromium, driven over its DevTools pipe (--remote-debugging-pipe, one browser for every
    page), the gallery and every rendered page after its load event: every <img> loaded
    (naturalWidth > 0), no console message, no exception and no failed load at all (the pages
    log nothing, so any message is an error), no raw TeX in the visible text ($$, \frac or
    any \command outside code), every <math> laid out (MathML, no script), every relative
    link reaching a file and every #anchor an id of its page; in the gallery every chapter
    section has its conclusion, a chapter that ran has its key figure and three numbers
    checked against theory, every figure named by what it shows (not its file name), and no
    "None" nor a placeholder caption even in the folded parts; a screenshot of the gallery (a
    PNG of the window's width).
Exit status: 0 passed, 1 failed (each failure printed), 77 skipped (CTest SKIP_RETURN_CODE):
Chromium is not installed.
"""

import argparse
import base64
import html.parser
import json
import os
import re
import shutil
import signal
import struct
import subprocess
import sys
import time
from pathlib import Path
from urllib.parse import unquote, urlparse

SKIP = 77
WINDOW = (1280, 2400)

# Tiny but complete runs (plots included), a second or two each.
TINY = {
    "ch01_ray_tracing": ["--width", "16", "--height", "12", "--spp", "2"],
    "ch02_disk_area": ["--max-n", "1000", "--trials", "10", "--dims", "2,3", "--ball-n", "500",
                       "--points", "50"],
    "ch03_trapezoid_vs_mc": ["--trials", "4", "--max-evaluations", "4096", "--dims", "1,2,3"],
    "ch04_recursive_nk": ["--width", "16", "--height", "12", "--branching", "1,2",
                          "--max-depth", "2", "--budget", "16", "--grid-spp", "16"],
    "ch05_path_tracer": ["--width", "16", "--height", "12", "--spp", "1,4", "--depth", "3"],
    "ch06_russian_roulette": ["--width", "16", "--height", "12", "--spp", "4", "--paths", "2000"],
    "ch07_importance_sampling": ["--width", "16", "--height", "12", "--spp", "2",
                                 "--reference-spp", "8"],
    "ch08_next_event_estimation": ["--width", "16", "--height", "12", "--spp", "2",
                                   "--reference-spp", "8", "--ray-budgets", "8,16",
                                   "--plates-spp", "1"],
    "ch09_stratified_qmc": ["--trials", "4", "--max-n", "256", "--budget", "256", "--dims", "1,2,3",
                            "--picture-points", "16"],
}
# Every chapter section's numbers checked against theory (scripts/make-gallery, LESSONS).
CHECKS_PER_CHAPTER = 3
# What raw TeX looks like when pandoc did not turn it into MathML.
RAW_TEX = re.compile(r"\$\$|\\frac|\\[A-Za-z]{2,}")
# Chromium's start and one page load take about a second each here; the whole browser part
# (the gallery and about 20 pages) has this long before the test gives up on it.
BROWSER_SECONDS = 150
# A chapter folder no program wrote: names and a summary that must be escaped in the page.
ODD_FOLDER = "ch99_odd & <name>"
ODD_IMAGE = "a \"quoted\" <image> & 50%.png"
INJECTED = "<img src=x onerror=\"console.error('injected')\"> a sentence from summary.json"

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
    return condition


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class PageParser(html.parser.HTMLParser):
    """Every <img src>, <a href>, <script src>, <link href> and the visible text."""

    def __init__(self):
        super().__init__()
        self.images, self.links, self.external, self.text = [], [], [], []

    def handle_starttag(self, tag, attrs):
        attributes = dict(attrs)
        if tag == "img":
            self.images.append(attributes.get("src", ""))
        elif tag == "a":
            self.links.append(attributes.get("href", ""))
        elif tag in ("script", "link", "iframe", "object", "embed") and (
                attributes.get("src") or attributes.get("href")):
            self.external.append(f"<{tag}> {attributes.get('src') or attributes.get('href')}")

    def handle_data(self, data):
        self.text.append(data)


def run_chapters(chapters, out):
    for name, program in chapters.items():
        if not check(os.access(program, os.X_OK), f"{name}: no program at {program} (build it)"):
            continue
        command = [program, "--out", str(out / name), "--threads", "2", "--quiet",
                   *TINY.get(name, [])]
        result = subprocess.run(command, capture_output=True, text=True, timeout=120)
        check(result.returncode == 0,
              f"{' '.join(command)}: exit {result.returncode}: {result.stderr.strip()}")


def add_odd_folder(out):
    odd = out / ODD_FOLDER
    odd.mkdir()
    source = next(out.glob("ch*/*.png"), None)
    if source:
        shutil.copy(source, odd / ODD_IMAGE)
    summary = {"chapter": "ch99", "note": INJECTED, "fitted_slope": -0.5, "theory_slope": -0.5,
               "flags": {"seed": "1", "odd": "<b>&</b>"}}
    (odd / "summary.json").write_text(json.dumps(summary), encoding="utf-8")


def check_page_source(page, parser, chapters, repo):
    for kind, values in (("img src", parser.images), ("a href", parser.links)):
        for value in values:
            check(value and not re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:|^/", value) or
                  value.startswith("#"), f"{kind} not relative: {value!r}")
    check(not parser.external, f"external resources: {parser.external}")
    check(not re.search(r"@import|@font-face|url\(", page), "CSS that loads a resource")
    check(parser.images, "no <img> in the page")
    text = "".join(parser.text)
    for name in chapters:
        check(name in text, f"chapter {name} missing from the page")
    not_run = [p.name for p in (repo / "chapters").glob("[0-9][0-9]_*")
               if f"ch{p.name}" not in chapters]
    for folder in not_run:
        check(re.search(rf"ch{re.escape(folder)}\s*not run", text),
              f"ch{folder} is not listed as not run")
    check(INJECTED in text, "the summary's sentence is not shown as text")
    check("onerror" not in "".join(f"{t}" for t in re.findall(r"<img[^>]*>", page)),
          "text from summary.json became markup")
    check(ODD_FOLDER in text and "a \"quoted\" <image>" in text, "the odd file names are not shown")


class Chromium:
    """Headless Chromium driven over its DevTools pipe: fd 3 carries our commands to it, fd 4
    its answers and events, each a JSON message ended by a NUL byte."""

    def __init__(self, executable, profile):
        to_browser, self.to_browser = os.pipe()
        self.from_browser, from_browser = os.pipe()

        def wire():  # in the child: the pipe ends as fds 3 and 4, kept across exec
            read_end, write_end = os.dup(to_browser), os.dup(from_browser)
            os.dup2(read_end, 3)
            os.dup2(write_end, 4)

        # Without the sandbox: Chromium refuses to run as root with it, and many CI containers
        # have no user namespaces for it. The pages are our own files, opened offline.
        command = [executable, "--headless", "--no-sandbox", "--disable-gpu",
                   "--disable-dev-shm-usage", "--no-first-run", "--no-default-browser-check",
                   "--disable-extensions", f"--user-data-dir={profile}",
                   f"--window-size={WINDOW[0]},{WINDOW[1]}", "--remote-debugging-pipe",
                   "about:blank"]
        self.process = subprocess.Popen(command, preexec_fn=wire, close_fds=False,
                                        stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                        stderr=subprocess.PIPE)
        os.close(to_browser)
        os.close(from_browser)
        self.buffer, self.next_id, self.events = b"", 0, []
        self.deadline = time.monotonic() + BROWSER_SECONDS
        target = self.send("Target.createTarget", url="about:blank")["targetId"]
        self.session = self.send("Target.attachToTarget", targetId=target,
                                 flatten=True)["sessionId"]
        for domain in ("Page", "Runtime", "Log"):
            self.send(f"{domain}.enable", session=True)

    def read_message(self):
        while b"\0" not in self.buffer:
            if time.monotonic() > self.deadline:
                raise TimeoutError(f"Chromium did not answer within {BROWSER_SECONDS} s")
            chunk = os.read(self.from_browser, 1 << 16)
            if not chunk:
                raise EOFError("Chromium closed its pipe: " +
                               self.process.stderr.read().decode(errors="replace")[-1500:])
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def send(self, method, session=False, **params):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params}
        if session:
            message["sessionId"] = self.session
        os.write(self.to_browser, json.dumps(message).encode() + b"\0")
        while True:
            answer = self.read_message()
            if answer.get("id") == self.next_id:
                if "error" in answer:
                    raise RuntimeError(f"{method}: {answer['error']}")
                return answer.get("result", {})
            self.events.append(answer)

    def wait_for(self, method):
        while True:
            for index, event in enumerate(self.events):
                if event.get("method") == method:
                    del self.events[index]
                    return event
            self.events.append(self.read_message())

    def open(self, path):
        """Loads PATH; returns the messages it logged (console, exceptions, failed loads)."""
        # A blank page first, so that late messages of the previous page are not this one's.
        self.send("Page.navigate", session=True, url="about:blank")
        self.wait_for("Page.loadEventFired")
        self.send("Runtime.evaluate", session=True, expression="0")
        self.events.clear()
        self.send("Page.navigate", session=True, url=path.as_uri())
        self.wait_for("Page.loadEventFired")
        # Anything still queued (a late console message) arrives before this answer.
        self.send("Runtime.evaluate", session=True, expression="0")
        logged = []
        for event in self.events:
            method, params = event.get("method"), event.get("params", {})
            if method == "Runtime.consoleAPICalled":
                logged.append("console." + params.get("type", "?") + ": " + " ".join(
                    str(a.get("value", a.get("description", ""))) for a in params.get("args", [])))
            elif method == "Runtime.exceptionThrown":
                logged.append("exception: " + json.dumps(params.get("exceptionDetails", {}))[:300])
            elif method == "Log.entryAdded":
                entry = params.get("entry", {})
                logged.append(f"log {entry.get('level')}: {entry.get('text')} {entry.get('url', '')}")
        return logged

    def evaluate(self, expression):
        result = self.send("Runtime.evaluate", session=True, expression=expression,
                           returnByValue=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"evaluate: {result['exceptionDetails']}")
        return result["result"].get("value")

    def screenshot(self, path):
        data = self.send("Page.captureScreenshot", session=True, format="png")["data"]
        path.write_bytes(base64.b64decode(data))

    def close(self):
        try:
            self.send("Browser.close")
        except (OSError, EOFError, RuntimeError, TimeoutError):
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        os.close(self.to_browser)
        os.close(self.from_browser)


# What the checks read from a loaded page: its images, its visible text outside code and maths,
# its <math> boxes, its links and ids, and the gallery's chapter sections.
INSPECT = r"""(() => {
  const images = Array.from(document.images);
  const text = document.body.cloneNode(true);
  text.querySelectorAll('pre, code, math, script, style').forEach(e => e.remove());
  const sections = Array.from(document.querySelectorAll('section.chapter')).map(s => ({
    id: s.id,
    conclusion: (s.querySelector('p.conclusion') || {innerText: ''}).innerText.trim(),
    notRun: s.querySelector('.notrun') !== null,
    keyFigure: s.querySelector('figure.key img') !== null,
    checks: s.querySelectorAll('table.checks tr td:first-of-type').length,
    doc: (s.querySelector('a.doc') || {getAttribute: () => ''}).getAttribute('href'),
  }));
  return {
    images: images.length,
    broken: images.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src')),
    text: text.textContent,
    visible: document.body.innerText,
    maths: document.querySelectorAll('math').length,
    unlaid: Array.from(document.querySelectorAll('math')).filter(
      m => m.getBoundingClientRect().width === 0).length,
    links: Array.from(document.querySelectorAll('a[href]')).map(a => a.getAttribute('href')),
    ids: Array.from(document.querySelectorAll('[id]')).map(e => e.id),
    sections: sections,
    figures: Array.from(document.querySelectorAll('section.chapter figure')).map(f => ({
      section: f.closest('section').id,
      src: (f.querySelector('img') || {getAttribute: () => ''}).getAttribute('src'),
      name: (f.querySelector('figcaption b') || {textContent: ''}).textContent.trim(),
    })),
  };
})()"""


def ids_of(page, cache):
    if page not in cache:
        text = page.read_text(encoding="utf-8", errors="replace") if page.is_file() else ""
        cache[page] = set(re.findall(r'\bid="([^"]*)"', text)) | \
            set(re.findall(r"\bid=([^\s\"'>]+)", text))
    return cache[page]


def check_links(page, links, ids, cache):
    for link in links:
        parsed = urlparse(link)
        if parsed.scheme or link.startswith("//"):
            continue  # checked in the source: no page links out
        target = (page.parent / unquote(parsed.path)).resolve() if parsed.path else page
        if not check(os.path.exists(target), f"{page.name}: link {link!r} reaches no file"):
            continue
        if parsed.fragment and target.suffix == ".html":
            known = set(ids) if target == page else ids_of(target, cache)
            check(unquote(parsed.fragment) in known,
                  f"{page.name}: link {link!r}: no id {parsed.fragment!r} in {target.name}")


def check_page(browser, page, cache, gallery=False):
    logged = browser.open(page)
    seen = browser.evaluate(INSPECT)
    where = page.name if not gallery else "the gallery"
    check(not logged, f"{where}: messages:\n  " + "\n  ".join(logged))
    check(not seen["broken"], f"{where}: images that did not load: {seen['broken']}")
    raw = sorted(set(RAW_TEX.findall(seen["text"])))
    check(not raw, f"{where}: raw TeX in the visible text: {raw[:5]}")
    check(seen["unlaid"] == 0, f"{where}: {seen['unlaid']} of {seen['maths']} <math> not laid out")
    check_links(page, seen["links"], seen["ids"], cache)
    return seen


def check_gallery(seen, chapters):
    sections = {s["id"]: s for s in seen["sections"]}
    for name in chapters:
        section = sections.get(name)
        if not check(section, f"the gallery: no section {name}"):
            continue
        check(len(section["conclusion"]) > len("Conclusion. ") + 20,
              f"{name}: no conclusion ({section['conclusion']!r})")
        check(section["keyFigure"], f"{name}: no key figure")
        check(section["checks"] == CHECKS_PER_CHAPTER,
              f"{name}: {section['checks']} numbers checked against theory, not "
              f"{CHECKS_PER_CHAPTER}")
        check(re.fullmatch(r"docs/\d\d_[\w-]+\.html", section["doc"] or ""),
              f"{name}: the lesson link is {section['doc']!r}, not the rendered page")
    for section in seen["sections"]:
        if section["notRun"]:
            check(section["conclusion"], f"{section['id']} (not run): no conclusion")
    for shown in seen["figures"]:
        if shown["section"] not in chapters:
            continue  # a folder no chapter wrote: its images have only their names
        stem = Path(unquote(shown["src"])).stem
        check(shown["name"] and shown["name"].lower() != stem.replace("_", " ").lower(),
              f"{shown['section']}: the figure {stem} is named by its file, not what it shows")
    # The text of the whole page, the folded <details> too (innerText leaves those out).
    check(not re.search(r"\bNone\b", seen["text"]), "the gallery shows 'None'")
    check(not re.search(r"The plot \S+ draws|An image the chapter wrote", seen["text"]),
          "the gallery has placeholder captions")


def check_odd_shapes(make_gallery, tmp):
    """A summary.json of a shape the lessons do not expect (a number where a list was, texts
    where numbers were) still gives a page: the section says it could check nothing."""
    out = tmp / "shapes"
    odd = {"ch04_recursive_nk": {"sweep": 5, "missing_light": [1, 2], "equal_cost": "x"},
           "ch05_path_tracer": {"rmse_vs_spp": [{"spp": None, "rmse": "0.1"}], "rmse_slope": "x"},
           "ch08_next_event_estimation": {"shootout": [{"scene": "cornell", "light_scale": 0.1,
                                                        "estimator": "uniform",
                                                        "rays_per_pixel": 0, "rel_mse": 0}]}}
    for name, summary in odd.items():
        (out / name).mkdir(parents=True)
        (out / name / "summary.json").write_text(json.dumps(summary), encoding="utf-8")
    result = subprocess.run([sys.executable, make_gallery, "--out", str(out)],
                            capture_output=True, text=True, timeout=60)
    if check(result.returncode == 0, f"make-gallery on odd summaries: exit {result.returncode}: "
             f"{result.stderr[-600:]}"):
        page = (out / "index.html").read_text(encoding="utf-8")
        notes = page.count("No number of this run could be checked against theory")
        check(notes == len(odd), f"make-gallery on odd summaries: {notes} sections say they "
              f"could check nothing, not {len(odd)}")


def check_bad_flags(scripts, tmp):
    """A bad flag: exit 2, one line naming it, nothing written. An empty --out is one (it would
    be the current folder: the repository's own docs/, say)."""
    where = tmp / "flags"
    where.mkdir()
    for script in scripts:
        for flags, named in ((["--out="], "--out"), (["--out", ""], "--out"),
                             (["--bogus"], "--bogus")):
            result = subprocess.run([sys.executable, script, *flags], cwd=where,
                                    capture_output=True, text=True, timeout=60)
            lines = result.stderr.strip().splitlines()
            check(result.returncode == 2 and len(lines) == 1 and named in lines[0],
                  f"{Path(script).name} {' '.join(flags)}: exit {result.returncode}, "
                  f"stderr {result.stderr!r}")
    check(not any(where.iterdir()), f"a bad flag wrote {sorted(p.name for p in where.iterdir())}")


def check_foreign_docs(render_docs, tmp):
    """render-docs leaves an OUT/docs/ it did not write alone: exit 2, one line naming it."""
    out = tmp / "foreign"
    (out / "docs").mkdir(parents=True)
    mine = out / "docs" / "notes.html"
    mine.write_text("my notes", encoding="utf-8")
    # The refusal comes before any pandoc: 120 s only stops a hung script.
    result = subprocess.run([sys.executable, render_docs, "--out", str(out)],
                            capture_output=True, text=True, timeout=120)
    check(result.returncode == 2, f"render-docs over a foreign docs/: exit {result.returncode}")
    lines = result.stderr.strip().splitlines()
    check(len(lines) == 1 and "docs" in lines[0],
          f"render-docs over a foreign docs/: stderr {result.stderr!r}")
    check(mine.read_text(encoding="utf-8") == "my notes" and
          sorted(p.name for p in (out / "docs").iterdir()) == ["notes.html"] and
          [p.name for p in out.iterdir()] == ["docs"], "render-docs touched a foreign docs/")


def check_interrupted_docs(render_docs, tmp):
    """render-docs stopped by SIGTERM (scripts/run-chapters stops it so when its build fails)
    exits 143 and leaves no staging folder and no docs/."""
    out = tmp / "interrupted"
    out.mkdir()
    process = subprocess.Popen([sys.executable, render_docs, "--out", str(out)],
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60  # the staging folder comes before the first pandoc
    while not any(out.glob(".docs.staging-*")) and time.monotonic() < deadline:
        time.sleep(0.01)
    check(any(out.glob(".docs.staging-*")), "render-docs made no staging folder in 60 s")
    process.send_signal(signal.SIGTERM)
    _, stderr = process.communicate(timeout=120)  # the pages under way finish: seconds
    check(process.returncode == 143, f"render-docs after SIGTERM: exit {process.returncode}, "
          f"stderr {stderr!r}")
    check(not any(out.iterdir()),
          f"render-docs after SIGTERM left {sorted(p.name for p in out.iterdir())}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--tmp", required=True, type=Path)
    parser.add_argument("--make-gallery", required=True)
    parser.add_argument("--chapter", action="append", default=[], metavar="NAME=PATH")
    args = parser.parse_args()
    chromium = find_chromium()
    if not chromium:
        print("SKIPPED: chromium is not installed (apt-get install chromium, or "
              "scripts/test --browser)")
        return SKIP
    chapters = dict(item.split("=", 1) for item in args.chapter)
    if args.tmp.exists():
        shutil.rmtree(args.tmp)
    out = args.tmp / "out"
    out.mkdir(parents=True)

    start = time.monotonic()
    run_chapters(chapters, out)
    add_odd_folder(out)
    render_docs = str(Path(args.make_gallery).resolve().parent / "render-docs")
    if not shutil.which("pandoc"):
        print("FAILED: pandoc is not installed (apt-get install pandoc; every script of "
              "scripts/ installs it)")
        return 1
    for command in ([render_docs, "--out", str(out)], [args.make_gallery, "--out", str(out)]):
        # render-docs runs pandoc on some 20 pages (seconds); 300 s only stops a hung one.
        result = subprocess.run([sys.executable, *command], capture_output=True, text=True,
                                timeout=300)
        if not check(result.returncode == 0 and not result.stderr,
                     f"{Path(command[0]).name} exit {result.returncode}: {result.stderr}"):
            print("\n".join(failures))
            return 1
    page_path = out / "index.html"
    page = page_path.read_text(encoding="utf-8")
    source = PageParser()
    source.feed(page)
    repo = Path(args.make_gallery).resolve().parent.parent
    check_page_source(page, source, list(chapters) + [ODD_FOLDER], repo)
    check_foreign_docs(render_docs, args.tmp)
    check_interrupted_docs(render_docs, args.tmp)
    check_odd_shapes(args.make_gallery, args.tmp)
    check_bad_flags([render_docs, args.make_gallery], args.tmp)
    pages = sorted((out / "docs").rglob("*.html"))
    check(len(pages) >= len(list((repo / "docs").glob("*.md"))),
          f"{len(pages)} rendered pages for {len(list((repo / 'docs').glob('*.md')))} in docs/")
    runs = time.monotonic() - start

    start = time.monotonic()
    browser = Chromium(chromium, args.tmp / "profile")
    try:
        cache = {}
        seen = check_page(browser, page_path, cache, gallery=True)
        check(seen["images"] == len(source.images),
              f"the browser saw {seen['images']} images, the page has {len(source.images)}")
        check_gallery(seen, chapters)
        screenshot = args.tmp / "screenshot.png"
        browser.screenshot(screenshot)
        for rendered in pages:
            check_page(browser, rendered, cache)
    except (OSError, EOFError, RuntimeError, TimeoutError) as error:
        check(False, f"Chromium: {error}")
        screenshot = None
    finally:
        browser.close()
    seconds = time.monotonic() - start
    if screenshot:
        data = screenshot.read_bytes() if screenshot.exists() else b""
        if check(data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 1000,
                 f"no screenshot PNG at {screenshot} ({len(data)} bytes)"):
            # The viewport: the window's width, its height less what headless keeps for itself.
            width, height = struct.unpack(">II", data[16:24])
            check(width == WINDOW[0] and 0 < height <= WINDOW[1],
                  f"screenshot {width}x{height}, window {WINDOW[0]}x{WINDOW[1]}")
    print(f"{len(chapters)} tiny chapter runs, render-docs and make-gallery: {runs:.1f} s; "
          f"Chromium ({chromium}): the gallery and {len(pages)} pages in {seconds:.1f} s; "
          f"{len(source.images)} images in the gallery; screenshot {screenshot}")
    if failures:
        print("FAILED:\n" + "\n".join(failures))
        return 1
    print("passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
