"""The HTML page of `replay -o OUT.html` in a real browser (Debian's chromium, headless, driven
over its DevTools pipe): the frame shown for OUT.html#step=N is the replayer's frame N, pixel for
pixel; the keys, buttons, slider and address move the step; the page loads nothing from the
network and logs no error. Usage: test_html_page.py SCANTRACE WORKDIR. Exit 77: skipped."""
import os
import sys
import subprocess

import cdp
import images

SKIP = 77


def run(scantrace, *args, cwd):
    r = subprocess.run([scantrace, *args], cwd=cwd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"scantrace {' '.join(args)} failed ({r.returncode}): {r.stderr}")
    return r


def main():
    scantrace, work = sys.argv[1], sys.argv[2]
    if not cdp.find_chromium():
        print("SKIPPED: chromium is not installed (scripts/deps.sh installs it)")
        return SKIP
    os.makedirs(work, exist_ok=True)
    # A triangle small enough for big cells; rows 2..27, one step per scanline, so the step of a
    # row is known by hand: title, set-up, three edge-table entries, then row 2 is step 6.
    run(scantrace, "-q", "trace", "--triangle", "2.3,1.2 29,9.5 8,27.6", "--size", "32x30",
        "-o", "t.jsonl", cwd=work)
    common = ["--video-size", "640x360", "--rows-per-step", "1"]
    # The page of pre-drawn frames (the trace page is web/tests/chromium_trace_page.mjs's).
    run(scantrace, "-q", "replay", "t.jsonl", "-o", "t.html", "--frames-page", *common, cwd=work)
    run(scantrace, "-q", "replay", "t.jsonl", "-o", "frames/", *common, cwd=work)
    names = sorted(os.listdir(os.path.join(work, "frames")))
    frames = images.decode_sequence(os.path.join(work, "frames", "frame_%05d.png"), len(names),
                                    640, 360)
    total = len(frames)
    assert total == 1 + 1 + 3 + 26 + 1 + 1, f"{total} frames"

    html = open(os.path.join(work, "t.html"), encoding="utf-8").read()
    for outside in ('src="http', "src='http", 'href="http', "url(http", "@import", "<link"):
        assert outside not in html, f"the page refers to something outside: {outside}"

    browser = cdp.Browser()
    failures = []
    checks = [0]
    try:
        url = "file://" + os.path.abspath(os.path.join(work, "t.html"))
        browser.open(url + "#step=7")
        browser.call("Emulation.setDeviceMetricsOverride",
                     {"width": 1700, "height": 1000, "deviceScaleFactor": 1, "mobile": False})
        browser.wait_for("document.readyState === 'complete' && "
                         "document.getElementById('frame').complete && "
                         "document.getElementById('frame').naturalWidth > 0")

        def step():
            return int(browser.evaluate("document.getElementById('slider').value"))

        def shown_frame():
            browser.wait_for("document.getElementById('frame').complete")
            rect = browser.evaluate(
                "(() => { const r = document.getElementById('frame').getBoundingClientRect();"
                " return {x: r.x, y: r.y, width: r.width, height: r.height}; })()")
            return images.decode(browser.screenshot(rect))

        def expect(n, what):
            checks[0] += 1
            s = step()
            h = browser.evaluate("location.hash")
            if s != n or h != f"#step={n}":
                failures.append(f"{what}: step {s}, address {h}; expected step {n}")
                return
            image = shown_frame()
            best, d = images.closest(image, frames)
            if best != n - 1 or d[n - 1] > 0.5:
                failures.append(f"{what}: the page shows frame {best + 1} (difference "
                                f"{d[n - 1]:.2f} to frame {n})")

        expect(7, "opened at #step=7")
        browser.key("ArrowRight", vk=39)
        browser.key("ArrowRight", vk=39)
        browser.key("ArrowLeft", vk=37)
        expect(8, "Right Right Left")
        browser.key("End", vk=35)
        expect(total, "End")
        browser.key("Home", vk=36)
        expect(1, "Home")
        browser.key("PageDown", code="PageDown", vk=34)
        expect(11, "PgDn")
        browser.key(" ", code="Space", vk=32, text=" ")
        expect(12, "space")
        for ch in "g15":
            browser.type_char(ch)
        browser.key("Enter", vk=13, text="\r")
        expect(6 + 15 - 2, "g 15 Enter")
        # The address drives the page too: a link to a step.
        browser.evaluate("location.hash = '#step=3'")
        browser.wait_for("document.getElementById('slider').value === '3'")
        expect(3, "address #step=3")
        # A click on the slider's right end: the last step; the address follows.
        rect = browser.evaluate(
            "(() => { const r = document.getElementById('slider').getBoundingClientRect();"
            " return {x: r.x, y: r.y, width: r.width, height: r.height}; })()")
        browser.click(rect["x"] + rect["width"] - 2, rect["y"] + rect["height"] / 2)
        browser.wait_for(f"document.getElementById('slider').value === '{total}'", timeout=5)
        expect(total, "slider click at its end")
        browser.click(rect["x"] + 2, rect["y"] + rect["height"] / 2)
        browser.wait_for("document.getElementById('slider').value === '1'", timeout=5)
        expect(1, "slider click at its start")
        # Play moves on by itself; pause stops it.
        browser.type_char("a")
        browser.wait_for("parseInt(document.getElementById('slider').value) >= 3", timeout=10)
        browser.type_char("a")
        paused = step()
        browser.evaluate("new Promise(r => setTimeout(r, 600))")
        if step() != paused:
            failures.append(f"a (pause): the step moved on from {paused} to {step()}")
        # The step list: a click on an entry jumps there.
        browser.evaluate("document.querySelectorAll('#list li')[4].click()")
        expect(5, "click on the fifth entry of the step list")
        errors = browser.errors()
        if errors:
            failures.append("console errors: " + "; ".join(errors))
        outside = [u for u in browser.requests()
                   if not (u.startswith("file:") or u.startswith("data:"))]
        if outside:
            failures.append("network requests: " + ", ".join(outside))
    finally:
        browser.close()
    for f in failures:
        print("FAILED:", f)
    print(f"the page in chromium: {checks[0]} steps compared with the replayer's frames, "
          f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
