"""Opening report pages in headless chromium: every <img> of a page must load. The report's
pages count the images that failed to load into <body data-broken-images> once loaded
(reports/generic/page.py); the DOM is dumped after that script has run."""
import glob
import html.parser
import os
import re
import subprocess


def flags(profile):
    return ["--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--mute-audio",
            "--no-first-run", f"--user-data-dir={profile}", "--virtual-time-budget=10000"]


class Imgs(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.srcs = []

    def handle_starttag(self, tag, attrs):
        if tag == "img":
            self.srcs.append(dict(attrs).get("src", ""))


def missing_files(page):
    """img sources of the page that name no file relative to the page's folder."""
    p = Imgs()
    with open(page) as f:
        p.feed(f.read())
    return [s for s in p.srcs if not os.path.isfile(os.path.join(os.path.dirname(page), s))], len(p.srcs)


def broken_in_browser(chromium, page, profile):
    """(images, broken) as the browser saw them, or raises when the page's count is absent."""
    r = subprocess.run([chromium] + flags(profile) + ["--dump-dom", "file://" + os.path.abspath(page)],
                       stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, timeout=240)
    m = re.search(r"<body[^>]*\bdata-images=\"(\d+)\"[^>]*\bdata-broken-images=\"(\d+)\"", r.stdout)
    if not m:
        raise RuntimeError(f"{page}: chromium gave no image count (exit {r.returncode}, "
                           f"{len(r.stdout)} bytes of DOM)")
    return int(m.group(1)), int(m.group(2))


def screenshot(chromium, page, png, profile, size="1400,2000"):
    subprocess.run([chromium] + flags(profile) + [f"--window-size={size}", f"--screenshot={os.path.abspath(png)}",
                    "file://" + os.path.abspath(page)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   timeout=240, check=False)
    return os.path.isfile(png) and os.path.getsize(png) > 0


def pages(folder):
    return sorted(glob.glob(os.path.join(folder, "*.html")))
