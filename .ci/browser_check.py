"""The built book in a real browser: headless Debian Chromium, driven by selenium through chromium-driver.

Serves ``build/book/_build/html`` on a free localhost port, loads the index and three chapters
(each must show its title and draw its figures), types a word into the search page's box and
waits for results, and saves a screenshot of each step in ``build/book/screenshots/``.
Exit status 0 when every step passes, 1 with the failed step named otherwise.

Usage: python .ci/browser_check.py [SITE]
"""

from __future__ import annotations

import functools
import http.server
import sys
import tempfile
import threading
from pathlib import Path

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support import expected_conditions
from selenium.webdriver.support.ui import WebDriverWait

REPO = Path(__file__).resolve().parents[1]
SITE = REPO / "build" / "book" / "_build" / "html"
SHOTS = REPO / "build" / "book" / "screenshots"
CHAPTERS = ["01-fe-tire-model", "04-cleat-test", "07-quarter-car"]
SEARCH_WORD = "tassello"


def serve(site: Path) -> tuple[http.server.ThreadingHTTPServer, str]:
    """A quiet HTTP server of ``site`` on a free port of localhost, running in a thread; and its address."""

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args) -> None:
            pass

    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=str(site)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}"


def browser(profile: str) -> webdriver.Chrome:
    """Headless Chromium with the flags this machine's closed network needs (no background traffic)."""
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for flag in (
        "--headless=new",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--window-size=1280,1600",
        f"--user-data-dir={profile}",
    ):
        options.add_argument(flag)
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


def figures_drawn(driver: webdriver.Chrome) -> tuple[int, int]:
    """(images on the page, images the browser decoded): a missing or broken figure has no width."""
    return driver.execute_script(
        "const imgs = [...document.querySelectorAll('main img, article img')];"
        "return [imgs.length, imgs.filter(i => i.complete && i.naturalWidth > 0).length];"
    )


def check(site: Path) -> list[str]:
    """Every step's failure, one line each (empty: all passed)."""
    failures = []
    SHOTS.mkdir(parents=True, exist_ok=True)
    server, address = serve(site)
    with tempfile.TemporaryDirectory() as profile:
        driver = browser(profile)
        wait = WebDriverWait(driver, 30)
        try:
            driver.get(f"{address}/index.html")
            wait.until(expected_conditions.presence_of_element_located((By.TAG_NAME, "h1")))
            if "roadnoise" not in driver.title:
                failures.append(f"index: title {driver.title!r} does not name the collection")
            driver.save_screenshot(str(SHOTS / "index.png"))
            for chapter in CHAPTERS:
                driver.get(f"{address}/notebooks/{chapter}.html")
                heading = wait.until(
                    expected_conditions.presence_of_element_located((By.CSS_SELECTOR, "main h1, article h1"))
                )
                wait.until(lambda d: d.execute_script("return document.readyState") == "complete")
                shown, drawn = figures_drawn(driver)
                if shown == 0 or drawn < shown:
                    failures.append(f"{chapter}: {drawn} of {shown} figures drawn")
                title = heading.get_attribute("textContent")
                if not title.startswith(chapter[:2]):
                    failures.append(f"{chapter}: heading {title!r}")
                driver.save_screenshot(str(SHOTS / f"{chapter}.png"))
            driver.get(f"{address}/search.html")
            boxes = [b for b in driver.find_elements(By.CSS_SELECTOR, "input[name='q']") if b.is_displayed()]
            if not boxes:
                failures.append("search: no visible search box")
            else:
                boxes[0].send_keys(SEARCH_WORD, Keys.ENTER)
                try:
                    wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, "#search-results li"))
                    found = len(driver.find_elements(By.CSS_SELECTOR, "#search-results li"))
                    print(f"search: {found} pages found for {SEARCH_WORD!r}")
                except Exception:  # noqa: BLE001 - a timeout is the failure reported
                    failures.append(f"search: no result for {SEARCH_WORD!r}")
                driver.save_screenshot(str(SHOTS / "search.png"))
        finally:
            driver.quit()
            server.shutdown()
    return failures


def main() -> int:
    site = Path(sys.argv[1]) if len(sys.argv) > 1 else SITE
    if not (site / "index.html").is_file():
        print(f"browser check: no book at {site}; build it first (python -m roadnoise_utils.repro.book)")
        return 1
    failures = check(site)
    for line in failures:
        print(f"browser check FAILED: {line}")
    print(f"browser check: {'passed' if not failures else 'failed'}; screenshots in {SHOTS}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
