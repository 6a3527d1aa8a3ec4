"""`lpvlab report`'s pages in a real browser (headless Chromium through Selenium): a sweep's, an
explanation's (`lpvlab explain`, class ExplanationInBrowser) and a tune's (`lpvlab tune`, TuneInBrowser).

Usage: report_browser_test.py LPVLAB_EXECUTABLE [--sweep DIR] [--screenshot PNG]
Runs a small sweep whose configurations compare with a path-traced reference (or takes the sweep
DIR, which `lpvlab report` has reported on), builds its report, opens DIR/report/index.html in
headless Chromium and checks that every image loads (decoded, not just requested), every link
resolves to a file of the sweep, and the console shows no error. --screenshot saves the top of
the page (the README's picture is that of experiments/ablation_occlusion.toml's sweep). Exits 77 (skipped, for ctest) when
Chromium, ChromeDriver or Selenium is missing, except under CI (env CI set), where that fails.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
import urllib.parse

ARGS = None

EXPERIMENT = """
[output]
width = 96
height = 96
[grid]
resolution = 8
[timing]
warmup = 0
repeats = 2
[reference]
compare = true
samples = 8
[sweep]
product = { "propagation.iterations" = [2, 8], "grid.resolution" = [8, 12] }
"""


def browser():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = shutil.which("chromium")
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--allow-file-access-from-files", "--window-size=1280,1000"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)


def run_lpvlab(work, *commands):
    """Runs each lpvlab command (a list of arguments) with the reference cache in `work`."""
    env = dict(os.environ, LPVLAB_CACHE_DIR=os.path.join(work, "cache"))
    for args in commands:
        r = subprocess.run([ARGS.lpvlab, *args], env=env, capture_output=True, text=True)
        if r.returncode != 0:
            raise AssertionError(f"lpvlab {' '.join(args)}: {r.stderr}")


def open_page(index):
    """A browser showing `index` once every image has finished loading (loaded or not)."""
    driver = browser()
    driver.get("file://" + urllib.parse.quote(index))
    driver.set_script_timeout(30)
    driver.execute_async_script("""
        const done = arguments[arguments.length - 1];
        Promise.all([...document.images].map(img => img.complete ? null :
            new Promise(r => { img.onload = img.onerror = r; }))).then(() => done());
    """)
    return driver


def image_states(driver):
    """[src, complete, natural width] of every image of the page."""
    return driver.execute_script("return [...document.images].map(i => [i.src, i.complete, i.naturalWidth]);")


class ReportInBrowser(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="lpvlab-report-browser-")
        if ARGS.sweep:
            cls.sweep = os.path.abspath(ARGS.sweep)
        else:
            path = os.path.join(cls.work, "browser.toml")
            with open(path, "w") as f:
                f.write(EXPERIMENT)
            cls.sweep = os.path.join(cls.work, "sweep")
            run_lpvlab(cls.work, ["sweep", path, "--out", cls.sweep], ["report", cls.sweep])
        with open(os.path.join(cls.sweep, "sweep.json")) as f:
            cls.configurations = len(json.load(f)["configurations"])
        cls.index = os.path.join(cls.sweep, "report", "index.html")
        cls.driver = open_page(cls.index)

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()
        shutil.rmtree(cls.work, ignore_errors=True)

    def test_every_image_loads(self):
        images = image_states(self.driver)
        self.assertGreater(len(images), 4)  # plots, the reference and each configuration's images
        for src, complete, width in images:
            self.assertTrue(complete and width > 0, f"image did not load: {src}")

    def test_every_link_resolves_to_a_file_of_the_sweep(self):
        links = self.driver.execute_script("return [...document.links].map(a => a.href);")
        self.assertTrue(links)
        manifests = 0
        for href in links:
            url = urllib.parse.urlparse(href)
            if url.scheme in ("http", "https", "mailto"):
                continue  # the page may cite papers; this test is about the sweep's own files
            self.assertEqual(url.scheme, "file", href)
            path = urllib.parse.unquote(url.path)
            self.assertTrue(os.path.exists(path), f"broken link: {href}")
            self.assertTrue(os.path.realpath(path).startswith(os.path.realpath(self.sweep)), href)
            manifests += path.endswith("manifest.json")
        self.assertEqual(manifests, self.configurations)  # one per configuration

    def test_the_page_does_not_overflow_1280_px(self):
        # Wide tables (an ablation table has a column per metric) scroll inside their own box;
        # the page itself never needs a horizontal scroll bar in a 1280 px window.
        self.driver.set_window_size(1280, 1000)
        page, window = self.driver.execute_script(
            "return [document.documentElement.scrollWidth, document.documentElement.clientWidth];")
        self.assertLessEqual(page, window, "the page is wider than the window")

    def test_a_header_click_sorts_its_column_and_a_second_reverses_it(self):
        # The ablation table's third column (a metric: numbers), as the page shows it.
        column = '''
            var t = document.querySelector('table.ablation');
            return [...t.tBodies[0].rows].map(r => r.cells[2].textContent.trim());'''
        header = self.driver.execute_script(
            "return document.querySelector('table.ablation').tHead.rows[0].cells[2];")
        before = self.driver.execute_script(column)
        numbers = [float(v) for v in before if v not in ("", "inf")]
        self.assertGreater(len(set(numbers)), 1, before)  # something to sort
        header.click()
        ascending = [float(v) for v in self.driver.execute_script(column) if v not in ("", "inf")]
        self.assertEqual(ascending, sorted(numbers))
        self.assertEqual(header.get_attribute("aria-sort"), "ascending")
        header.click()
        descending = [float(v) for v in self.driver.execute_script(column) if v not in ("", "inf")]
        self.assertEqual(descending, sorted(numbers, reverse=True))
        self.assertEqual(header.get_attribute("aria-sort"), "descending")

    def test_a_click_flips_the_result_with_its_reference_and_a_double_click_zooms(self):
        from selenium.webdriver.common.action_chains import ActionChains
        flips = self.driver.find_elements("css selector", "img.flip")
        self.assertEqual(len(flips), self.configurations)  # every configuration has a reference
        img = flips[0]
        own, reference = img.get_attribute("src"), img.get_attribute("data-flip")
        self.driver.execute_script("arguments[0].scrollIntoView();", img)
        img.click()
        self.assertTrue(img.get_attribute("src").endswith(reference.lstrip("./")), img.get_attribute("src"))
        caption = img.find_element("xpath", "../figcaption").text
        self.assertIn("reference", caption)
        img.click()
        self.assertEqual(img.get_attribute("src"), own)
        natural = self.driver.execute_script("return arguments[0].naturalWidth;", img)
        ActionChains(self.driver).double_click(img).perform()
        width = self.driver.execute_script("return arguments[0].getBoundingClientRect().width;", img)
        self.assertAlmostEqual(width, 4 * natural, delta=2)
        self.assertEqual(self.driver.execute_script(
            "return getComputedStyle(arguments[0]).imageRendering;", img), "pixelated")
        ActionChains(self.driver).double_click(img).perform()  # back
        # Zoomed or not, the page itself never scrolls sideways (the figure scrolls).
        page, window = self.driver.execute_script(
            "return [document.documentElement.scrollWidth, document.documentElement.clientWidth];")
        self.assertLessEqual(page, window)

    def test_console_shows_no_error(self):
        errors = [e for e in self.driver.get_log("browser") if e["level"] in ("SEVERE", "ERROR")]
        self.assertEqual(errors, [])

    def test_screenshot(self):
        if not ARGS.screenshot:
            self.skipTest("no --screenshot asked for")
        self.driver.set_window_size(1280, ARGS.screenshot_height)
        self.assertTrue(self.driver.save_screenshot(ARGS.screenshot))


class ExplanationInBrowser(unittest.TestCase):
    """`lpvlab explain` on a small Cornell box and `lpvlab report` of its directory: the error
    budget's page (analysis/lpvlab_analysis/explain.py)."""

    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="lpvlab-explain-browser-")
        cls.dir = os.path.join(cls.work, "explained")
        small = ["-s", "output.width=64", "-s", "output.height=64", "-s", "grid.resolution=12",
                 "-s", "light_maps.rsm_resolution=64", "-s", "reference.samples=8", "--vpls", "128"]
        run_lpvlab(cls.work, ["explain", *small, "--out", cls.dir], ["report", cls.dir])
        cls.driver = open_page(os.path.join(cls.dir, "report", "index.html"))

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()
        shutil.rmtree(cls.work, ignore_errors=True)

    def test_the_chart_and_the_chain_load_and_the_stages_are_tabulated(self):
        images = image_states(self.driver)
        # The chart, the reference, the chain's four images and the light grids' slices.
        self.assertEqual(len(images), 1 + 5 + 1)
        self.assertTrue(any(src.endswith("img/grids.png") for src, _, _ in images), images)
        for src, complete, width in images:
            self.assertTrue(complete and width > 0, f"image did not load: {src}")
        stages = self.driver.execute_script(
            "return [...document.querySelectorAll('table')[1].tBodies[0].rows].map(r => r.cells[0].textContent);")
        self.assertEqual([s.split(" ")[0] for s in stages], ["propagation", "rendering", "occlusion", "injection"])

    def test_a_click_flips_an_oracle_with_the_reference(self):
        img = self.driver.find_elements("css selector", "img.flip")[0]
        own, reference = img.get_attribute("src"), img.get_attribute("data-flip")
        img.click()
        self.assertTrue(img.get_attribute("src").endswith(reference.lstrip("./")))
        img.click()
        self.assertEqual(img.get_attribute("src"), own)

    def test_no_overflow_and_no_console_error(self):
        self.driver.set_window_size(1280, 1000)
        page, window = self.driver.execute_script(
            "return [document.documentElement.scrollWidth, document.documentElement.clientWidth];")
        self.assertLessEqual(page, window)
        errors = [e for e in self.driver.get_log("browser") if e["level"] in ("SEVERE", "ERROR")]
        self.assertEqual(errors, [])


TUNE = """
[output]
width = 32
height = 32
[grid]
resolution = 8
[light_maps]
rsm_resolution = 32
[tune]
budget_ms = "baseline"
candidates = 2
eta = 2
rungs = [2, 4]
[tune.space]
"grid.resolution" = [6, 10]
"""


class TuneInBrowser(unittest.TestCase):
    """`lpvlab tune` on a tiny Cornell box and `lpvlab report` of its directory: the tune's page
    (analysis/lpvlab_analysis/tuning.py)."""

    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="lpvlab-tune-browser-")
        path = os.path.join(cls.work, "tune.toml")
        with open(path, "w") as f:
            f.write(TUNE)
        cls.dir = os.path.join(cls.work, "tuned")
        run_lpvlab(cls.work, ["tune", path, "--out", cls.dir], ["report", cls.dir])
        cls.driver = open_page(os.path.join(cls.dir, "report", "index.html"))

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()
        shutil.rmtree(cls.work, ignore_errors=True)

    def test_the_plot_loads_and_the_last_rung_is_tabulated(self):
        images = image_states(self.driver)
        self.assertEqual(len(images), 1)
        for src, complete, width in images:
            self.assertTrue(complete and width > 0, f"image did not load: {src}")
        ids = self.driver.execute_script(
            "return [...document.querySelector('table').tBodies[0].rows].map(r => r.cells[0].textContent);")
        self.assertIn("baseline", ids)

    def test_links_resolve_no_overflow_and_no_console_error(self):
        for href in self.driver.execute_script("return [...document.links].map(a => a.href);"):
            self.assertTrue(os.path.exists(urllib.parse.unquote(urllib.parse.urlparse(href).path)), href)
        page, window = self.driver.execute_script(
            "return [document.documentElement.scrollWidth, document.documentElement.clientWidth];")
        self.assertLessEqual(page, window)
        errors = [e for e in self.driver.get_log("browser") if e["level"] in ("SEVERE", "ERROR")]
        self.assertEqual(errors, [])


def missing():
    for tool in ("chromium", "chromedriver"):
        if shutil.which(tool) is None:
            return f"{tool} is not installed (Debian packages chromium, chromium-driver)"
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "Selenium is not installed (Debian package python3-selenium)"
    return None


def main():
    global ARGS
    parser = argparse.ArgumentParser()
    parser.add_argument("lpvlab")
    parser.add_argument("--sweep")
    parser.add_argument("--screenshot")
    parser.add_argument("--screenshot-height", type=int, default=1400)
    ARGS, rest = parser.parse_known_args()
    ARGS.lpvlab = os.path.abspath(ARGS.lpvlab)
    why = missing()
    if why:
        print(("error: " if os.environ.get("CI") else "skipped: ") + why)
        return 1 if os.environ.get("CI") else 77
    result = unittest.main(argv=[sys.argv[0], "-v", *rest], exit=False).result
    return 0 if result.wasSuccessful() else 1


if __name__ == "__main__":
    sys.exit(main())
