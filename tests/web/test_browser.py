"""One real browser: Debian's Chromium, headless, driven by Selenium through
the system's chromedriver, against `mmt-plans serve` started in its own
process. A student opens a variant, gives name and group, types values
read off a drawing (F_bal by the force plans wrong by a known mistake: the
inertia forces and moments left out), submits, and reads each verdict and
cause on the page: the same as `mmt-plans check` gives for the same values,
without the exact values. The instructor's table and CSV list the
submission, and after a restart of the server it is still there.

Skipped, saying why, where chromium, chromedriver or selenium are missing
(`make test` installs chromium and chromium-driver with apt where it can).
With MMT_PLANS_WEB_SHOTS=DIR it also saves a screenshot of each page there
(docs/web/ holds the ones in the README)."""

import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

import pytest

from tests.web.conftest import SEED003, VARIANT, answers_toml

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
CHROMEDRIVER = shutil.which("chromedriver") or "/usr/bin/chromedriver"
PASSWORD = "browser-test-password"

pytestmark = pytest.mark.skipif(
    not (Path(CHROMIUM).is_file() and Path(CHROMEDRIVER).is_file()),
    reason="the browser test needs Debian's chromium and chromium-driver "
    "(apt-get install chromium chromium-driver; `make test` does it where it can)",
)


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Server:
    """`mmt-plans serve` in its own process."""

    def __init__(self, tasks, db, port):
        self.url = f"http://127.0.0.1:{port}"
        env = {**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[2])}
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "mmt_plans", "serve", str(tasks), "--port", str(port),
             "--db", str(db), "--password", PASSWORD],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env, text=True,
        )
        deadline = time.monotonic() + 60
        while True:
            try:
                urllib.request.urlopen(self.url + "/", timeout=5).read()
                return
            except OSError:
                if self.proc.poll() is not None or time.monotonic() > deadline:
                    out = self.proc.stdout.read() if self.proc.poll() is not None else ""
                    self.stop()
                    raise RuntimeError(f"mmt-plans serve did not start: {out}")
                time.sleep(0.2)

    def get(self, path):
        req = urllib.request.Request(self.url + path, headers={"Authorization": f"Bearer {PASSWORD}"})
        return urllib.request.urlopen(req, timeout=60).read().decode("utf-8")

    def stop(self):
        self.proc.terminate()
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


@pytest.fixture
def browser():
    webdriver = pytest.importorskip("selenium.webdriver", reason="the browser test needs selenium (pip)")
    from selenium.webdriver.chrome.service import Service

    profile = tempfile.mkdtemp(prefix="mmt-web-chromium-")
    opts = webdriver.ChromeOptions()
    opts.binary_location = CHROMIUM
    for arg in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                f"--user-data-dir={profile}", "--window-size=1280,1000"):
        opts.add_argument(arg)
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=opts)
    driver.set_page_load_timeout(120)
    yield driver
    driver.quit()
    shutil.rmtree(profile, ignore_errors=True)


def _shot(driver, name):
    folder = os.environ.get("MMT_PLANS_WEB_SHOTS")
    if not folder:
        return
    Path(folder).mkdir(parents=True, exist_ok=True)
    height = driver.execute_script("return document.documentElement.scrollHeight")
    driver.set_window_size(1280, min(max(height, 700), 4000))
    driver.execute_script("window.scrollTo(0, 0)")
    driver.save_screenshot(str(Path(folder) / f"{name}.png"))
    driver.set_window_size(1280, 1000)


def _click_to_next_page(driver, element, timeout=30):
    """Click `element` and wait until the page it leads to has replaced this
    one (a click returns before the next page is there, and the index and
    the variant page both hold the student form): the old page's window
    carries a mark the new one has not."""
    from selenium.common.exceptions import WebDriverException
    from selenium.webdriver.support.ui import WebDriverWait

    driver.execute_script("window.mmtOldPage = true")
    element.click()

    def arrived(d):
        # While the old page is torn down, chromedriver may answer with
        # any WebDriverException (not only a stale element: "Node with
        # given id does not belong to the document"); that is "not yet".
        try:
            return d.execute_script(
                "return window.mmtOldPage === undefined && document.readyState === 'complete'"
            )
        except WebDriverException:
            return False

    WebDriverWait(driver, timeout).until(arrived)


def test_a_student_checks_values_in_a_real_browser(browser, tmp_path):
    from selenium.webdriver.common.by import By

    from mmt_plans import load
    from mmt_plans.solution import solve
    from mmt_plans.web.tasks import TaskDir
    from tests.web.conftest import student_values

    tasks = tmp_path / "tasks"
    tasks.mkdir()
    for stem in (VARIANT, "task02_v1", "task03_v1"):
        shutil.copy(SEED003 / f"{stem}.toml", tasks / f"{stem}.toml")
    db = tmp_path / "class.sqlite"
    values = student_values(TaskDir(tasks).variant(VARIANT))
    port = _free_port()
    server = Server(tasks, db, port)
    try:
        browser.get(server.url + "/")
        _shot(browser, "index")
        _click_to_next_page(browser, browser.find_element(By.LINK_TEXT, VARIANT))
        browser.find_element(By.ID, "name").send_keys("Olena Koval")
        browser.find_element(By.ID, "group").send_keys("MM-21")
        _click_to_next_page(browser, browser.find_element(By.ID, "save-student"))
        assert browser.find_element(By.ID, "who-name").text == "Olena Koval"
        for name, text in values.items():
            browser.find_element(By.NAME, name).send_keys(text)
        _shot(browser, "variant")
        _click_to_next_page(browser, browser.find_element(By.ID, "submit"))

        verdict = browser.find_element(By.ID, "verdict").text
        page = [
            (
                tr.get_attribute("data-what"),
                tr.find_element(By.CSS_SELECTOR, "td.verdict").text,
                tr.find_element(By.CSS_SELECTOR, "td.cause").text or None,
            )
            for tr in browser.find_elements(By.CSS_SELECTOR, "#report tbody tr")
        ]
        body = browser.find_element(By.TAG_NAME, "body").text
        _shot(browser, "result")

        # the same values through `mmt-plans check --json`, in its own process
        answers = tmp_path / "answers.toml"
        answers.write_text(answers_toml(values), encoding="utf-8")
        report = tmp_path / "report.json"
        run = subprocess.run(
            [sys.executable, "-m", "mmt_plans", "check", str(tasks / f"{VARIANT}.toml"), str(answers),
             "--json", str(report)],
            capture_output=True, text=True,
        )
        assert run.returncode == 1, run.stderr  # some value is out of the tolerance
        cli = json.loads(report.read_text(encoding="utf-8"))
        expected = [(v["what"], "pass" if v["passed"] else "FAIL", v["cause"]) for v in cli["values"]]
        assert page == expected
        assert ("F_bal (plans)", "FAIL", "inertia forces and moments of links 2–5 left out") in page
        assert verdict == "1 of 5 values out of the tolerance."
        exact = solve(load(tasks / f"{VARIANT}.toml"))
        for v in cli["values"]:  # no exact value, as check's table prints it
            assert f"{v['exact']:.6g}" not in body
        assert f"{exact.forces.balancing_force_plans:.4g}" not in body

        # the instructor's table and CSV list the submission
        browser.get(server.url + "/instructor")
        _shot(browser, "login")
        browser.get(server.url + f"/instructor?token={PASSWORD}")
        rows = browser.find_elements(By.CSS_SELECTOR, "#subs tbody tr")
        assert [[td.text for td in tr.find_elements(By.TAG_NAME, "td")][2:7] for tr in rows] == [
            ["MM-21", "Olena Koval", VARIANT, "form", "FAIL"]
        ]
        _shot(browser, "instructor")
        if os.environ.get("MMT_PLANS_WEB_SHOTS"):
            browser.find_element(By.LINK_TEXT, "1").click()
            _shot(browser, "submission")
            browser.get(server.url + f"/instructor/keys/{VARIANT}")
            _shot(browser, "keys")
            browser.get(server.url + "/variant/task03_v1?lang=uk")
            _shot(browser, "variant_uk")
            browser.get(server.url + "/?lang=en")
        csv_text = server.get("/instructor/submissions.csv")
        assert f"MM-21,Olena Koval,{VARIANT},form,no,5,1," in csv_text
    finally:
        server.stop()

    # stopped and started again on the same file: the submission is still there
    server = Server(tasks, db, _free_port())
    try:
        assert f"MM-21,Olena Koval,{VARIANT},form,no,5,1," in server.get("/instructor/submissions.csv")
    finally:
        server.stop()
