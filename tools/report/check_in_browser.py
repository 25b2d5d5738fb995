#!/usr/bin/python3
"""Opens report.html files in Debian's headless Chromium and checks what a reader would see.

    /usr/bin/python3 tools/report/check_in_browser.py REPORT.html [...] [--screenshot-dir DIR]

For each page:
- it is self-contained: no src/href to anything but data: URIs and in-page anchors;
- in the browser every <img> decodes (complete, naturalWidth > 0) and the page does not overflow
  the window sideways at 1200 px. The reports carry no JavaScript, so the probe script that reads
  this is inserted into a temporary copy of the page, never into the report itself;
- a full-height screenshot is not blank (at least 2% of its pixels differ from the background),
  kept in --screenshot-dir for a person to look at.
Exit code 0 when every page passes, 1 otherwise; 2 when Chromium is missing.
"""
import argparse
import html.parser
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

WIDTH = 1200
PROBE = """<script>
window.addEventListener('load', function () {
  var ok = 0, broken = 0;
  for (var i = 0; i < document.images.length; i++) {
    var im = document.images[i];
    if (im.complete && im.naturalWidth > 0) ok++; else broken++;
  }
  var b = document.body;
  b.setAttribute('data-probe-images-ok', ok);
  b.setAttribute('data-probe-images-broken', broken);
  b.setAttribute('data-probe-scroll-width', document.documentElement.scrollWidth);
  b.setAttribute('data-probe-inner-width', window.innerWidth);
  b.setAttribute('data-probe-height', document.documentElement.scrollHeight);
});
</script>"""


class Links(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.images = 0
        self.external = []

    def handle_starttag(self, tag, attrs):
        if tag == "img":
            self.images += 1
        for name, value in attrs:
            if name in ("src", "href") and value and not (value.startswith("data:") or value.startswith("#")):
                self.external.append(f"<{tag} {name}={value[:80]}>")


def chromium():
    for name in ("chromium", "chromium-browser", "chromium-headless-shell"):
        path = shutil.which(name)
        if path:
            return path
    return None


def browser(exe, args, url, timeout=120):
    cmd = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--hide-scrollbars",
           "--no-first-run", "--virtual-time-budget=10000", f"--window-size={WIDTH},900", *args, url]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)


def probe_values(dom):
    return {k: int(v) for k, v in re.findall(r'data-probe-([a-z-]+)="(\d+)"', dom)}


def blank_fraction(png_path):
    import matplotlib.image as mpimg  # Debian python3-matplotlib

    img = mpimg.imread(png_path)[..., :3]
    background = np.median(img.reshape(-1, 3), axis=0)
    differs = np.abs(img - background).sum(axis=2) > 0.05
    return float(differs.mean()), img.shape


def check_page(exe, path, shots):
    problems = []
    if not os.path.isfile(path):
        return ["no such file"]
    text = open(path, encoding="utf-8").read()
    links = Links()
    links.feed(text)
    if links.external:
        problems.append(f"not self-contained: {len(links.external)} outside references, e.g. {links.external[0]}")
    if links.images == 0:
        problems.append("no images")
    with tempfile.TemporaryDirectory() as tmp:
        probed = os.path.join(tmp, "probed.html")
        with open(probed, "w", encoding="utf-8") as f:
            f.write(text.replace("</body>", PROBE + "</body>", 1))
        dom = browser(exe, ["--dump-dom"], "file://" + probed)
        if dom.returncode != 0:
            return problems + [f"chromium --dump-dom failed ({dom.returncode}): {dom.stderr[-300:]}"]
        v = probe_values(dom.stdout)
        if "images-ok" not in v:
            return problems + ["the page's load event never came (no probe values in the DOM)"]
        if v["images-broken"] or v["images-ok"] != links.images:
            problems.append(f"{v['images-broken']} of {links.images} images do not decode "
                            f"({v['images-ok']} do)")
        if v["scroll-width"] > v["inner-width"]:
            problems.append(f"the page is {v['scroll-width']} px wide in a {v['inner-width']} px window")
        height = min(max(v.get("height", 900), 900), 16000)
    # report.html is named after its run directory; any other page after itself.
    stem = os.path.splitext(os.path.basename(path))[0]
    name = os.path.basename(os.path.dirname(os.path.abspath(path))) if stem == "report" else stem
    shot = os.path.join(shots, name + ".png")
    out = browser(exe, [f"--window-size={WIDTH},{height}", f"--screenshot={shot}"], "file://" + os.path.abspath(path))
    if out.returncode != 0 or not os.path.exists(shot):
        return problems + [f"chromium --screenshot failed ({out.returncode}): {out.stderr[-300:]}"]
    drawn, shape = blank_fraction(shot)
    if drawn < 0.02:
        problems.append(f"the screenshot is nearly blank ({100 * drawn:.1f}% of pixels drawn)")
    print(f"  {path}: {v['images-ok']} of {links.images} images decoded, {v['scroll-width']} px wide, {v['height']} px tall, "
          f"{100 * drawn:.0f}% of the screenshot drawn -> {shot}")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("pages", nargs="+")
    ap.add_argument("--screenshot-dir", default=None)
    a = ap.parse_args()
    exe = chromium()
    if not exe:
        print("check_in_browser: Chromium not found (scripts/install-deps.sh installs Debian's chromium)",
              file=sys.stderr)
        return 2
    shots = a.screenshot_dir or tempfile.mkdtemp(prefix="sloshsph-shots-")
    os.makedirs(shots, exist_ok=True)
    failed = 0
    for page in a.pages:
        problems = check_page(exe, page, shots)
        for p in problems:
            print(f"FAIL {page}: {p}")
        failed += bool(problems)
    print(f"check_in_browser: {len(a.pages) - failed} of {len(a.pages)} pages pass")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
