#!/usr/bin/env python3
"""The gallery page (scripts/make-gallery) opened in headless Chromium (issue #15, item 6).

  gallery_test.py --tmp DIR --make-gallery PATH --chapter NAME=PATH ...

Runs each chapter given with tiny flags into DIR/out/, adds a folder whose file names and
summary.json need escaping, runs make-gallery on DIR/out/, then checks:
  - the page by itself: every <img> and link relative (no scheme, no leading '/', no
    network), no external script, style or font, the chapters not run listed as "not run",
    the text taken from files escaped;
  - the page in Chromium (--dump-dom after the load event, one run): the page's own script
    counted every <img> with naturalWidth > 0 (data-broken-images="0", data-images equal to the
    <img> count of the file), no console message at all (the page logs nothing, so any
    message is an error: "Uncaught ...", a failed load), and a screenshot written (a PNG of the
    window's size).
Exit status: 0 passed, 1 failed (each failure printed), 77 skipped (CTest SKIP_RETURN_CODE):
Chromium is not installed.
"""

import argparse
import html.parser
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import time
from pathlib import Path

SKIP = 77
WINDOW = (1280, 2400)

# Tiny but complete runs (plots included), a second or two each.
TINY = {
    "ch01_ray_tracing": ["--width", "16", "--height", "12", "--spp", "2"],
    "ch02_disk_area": ["--max-n", "1000", "--trials", "10", "--dims", "2,3", "--ball-n", "500",
                       "--points", "50"],
    "ch05_path_tracer": ["--width", "16", "--height", "12", "--spp", "1,4", "--depth", "3"],
}
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


def open_in_chromium(chromium, page_path, tmp):
    screenshot = tmp / "screenshot.png"
    command = [chromium, "--headless", "--disable-gpu", "--disable-dev-shm-usage",
               "--no-first-run", "--no-default-browser-check", "--disable-extensions",
               f"--user-data-dir={tmp / 'profile'}", f"--window-size={WINDOW[0]},{WINDOW[1]}",
               "--enable-logging=stderr", "--v=0", f"--screenshot={screenshot}", "--dump-dom",
               page_path.as_uri()]
    # Without the sandbox: Chromium refuses to run as root with it, and many CI containers have
    # no user namespaces for it. The page is our own file, opened offline.
    command.insert(1, "--no-sandbox")
    start = time.monotonic()
    result = subprocess.run(command, capture_output=True, text=True, timeout=90)
    seconds = time.monotonic() - start
    check(result.returncode == 0, f"chromium exit {result.returncode}: {result.stderr[-2000:]}")
    return result.stdout, result.stderr, screenshot, seconds


def check_browser(dom, log, screenshot, image_count):
    body = re.search(r"<body([^>]*)>", dom)
    attributes = dict(re.findall(r'(data-[a-z-]+)="([^"]*)"', body.group(1))) if body else {}
    if check(attributes.get("data-checked") == "yes",
             f"the page's image check did not run (body attributes {attributes})"):
        check(attributes.get("data-broken-images") == "0",
              f"images that did not load: {attributes.get('data-broken-images')}; "
              + (re.search(r'<div id="broken"[^>]*>(.*?)</div>', dom, re.S) or [None, ""])[1])
        check(attributes.get("data-images") == str(image_count),
              f"the browser saw {attributes.get('data-images')} images, the page has {image_count}")
    console = [line for line in log.splitlines() if ":CONSOLE" in line or "Uncaught" in line]
    check(not console, "console messages:\n  " + "\n  ".join(console))
    data = screenshot.read_bytes() if screenshot.exists() else b""
    if check(data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 1000,
             f"no screenshot PNG at {screenshot} ({len(data)} bytes)"):
        size = struct.unpack(">II", data[16:24])
        check(size == WINDOW, f"screenshot {size[0]}x{size[1]}, window {WINDOW[0]}x{WINDOW[1]}")


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
    result = subprocess.run([sys.executable, args.make_gallery, "--out", str(out)],
                            capture_output=True, text=True, timeout=60)
    if not check(result.returncode == 0, f"make-gallery exit {result.returncode}: {result.stderr}"):
        print("\n".join(failures))
        return 1
    page_path = out / "index.html"
    page = page_path.read_text(encoding="utf-8")
    source = PageParser()
    source.feed(page)
    repo = Path(args.make_gallery).resolve().parent.parent
    check_page_source(page, source, list(chapters) + [ODD_FOLDER], repo)
    runs = time.monotonic() - start

    dom, log, screenshot, seconds = open_in_chromium(chromium, page_path, args.tmp)
    check_browser(dom, log, screenshot, len(source.images))
    print(f"{len(chapters)} tiny chapter runs and make-gallery: {runs:.1f} s; Chromium "
          f"({chromium}): {seconds:.1f} s; {len(source.images)} images; screenshot {screenshot}")
    if failures:
        print("FAILED:\n" + "\n".join(failures))
        return 1
    print("passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
