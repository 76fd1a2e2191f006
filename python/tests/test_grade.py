"""why, diff and check from Python against the command line they share their C++ with: the same
text, the same JSON, the same verdict; a scene given as a path, a dict or the course's arrays
gives the same answer; bad images and tolerances are one clear error."""

import json
import subprocess

import numpy as np
import pytest

import scantrace
from conftest import SCANTRACE, random_scene, write_scene_json


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    d = tmp_path_factory.mktemp("grade")
    v, f, c, z = random_scene(7, n_vertices=40, n_faces=50)
    return write_scene_json(d / "scene.json", v, f, c, z), (f, v, c, z)


def cli(*args, check=True):
    r = subprocess.run([SCANTRACE, "-q", *map(str, args)], capture_output=True, text=True)
    if check and r.returncode not in (0, 3):
        raise AssertionError(r.stderr)
    return r


@pytest.mark.parametrize("pixel", [(100, 200), (256, 256), (0, 0), (511, 300)])
def test_why_is_the_commands_text_and_json(scene, pixel):
    path, _ = scene
    story = scantrace.why(path, *pixel)
    assert str(story) == cli("why", path, *pixel).stdout
    assert json.loads(story.to_json()) == json.loads(cli("why", path, *pixel, "--json").stdout)
    assert story.pixel == pixel and (story.x, story.y) == pixel
    ref = scantrace.render(**scantrace.load_scene(path), dtype=np.float32)[pixel[1], pixel[0]]
    assert story.final["color"] == pytest.approx(ref.tolist(), abs=1e-6)


def test_why_takes_a_path_a_dict_or_the_course_arrays(scene):
    path, arrays = scene
    a = scantrace.why(path, 120, 210)
    b = scantrace.why(scantrace.load_scene(path), 120, 210)
    c = scantrace.why(arrays, 120, 210)
    assert a.to_json() == b.to_json() == c.to_json()


def test_why_options_reach_the_command(scene):
    path, _ = scene
    story = scantrace.why(path, 300, 100, shading="flat", fill_rule="closed")
    assert str(story) == cli("why", path, 300, 100, "--shading", "flat",
                             "--fill-rule", "closed").stdout
    assert story.shading == "flat" and story.fill_rule == "closed"


def student_image(path):
    """A render with a wrong pixel block and flipped: what diff must find."""
    img = scantrace.render(**scantrace.load_scene(path))
    img[100:110, 100:130] = [0.2, 0.4, 0.6]
    return img


@pytest.mark.parametrize("kind", ["float64", "float32", "uint8"])
def test_diff_is_the_commands_report(scene, tmp_path, kind):
    path, _ = scene
    img = student_image(path)
    if kind == "uint8":
        img = np.round(img * 255).astype(np.uint8)
    else:
        img = img.astype(kind)
    np.save(tmp_path / "img.npy", img)
    report = scantrace.diff(path, img)
    r = cli("diff", path, tmp_path / "img.npy", "--json")
    assert json.loads(report.to_json()) == json.loads(r.stdout)
    assert str(report) == cli("diff", path, tmp_path / "img.npy").stdout
    assert report.agrees is (r.returncode == 0) is False
    assert report.differing_pixels == sum(report.categories.values()) > 0
    # A path to the same .npy gives the same report.
    assert scantrace.diff(path, tmp_path / "img.npy").to_json() == report.to_json()


def test_diff_of_the_reference_agrees(scene):
    path, arrays = scene
    img = scantrace.render(**scantrace.load_scene(path))
    report = scantrace.diff(arrays, img)
    assert report.agrees and report.differing_pixels == 0 and not report.global_mistakes


def test_diff_image_is_the_left_part_of_the_commands_diff_png(scene, tmp_path):
    PIL = pytest.importorskip("PIL.Image")
    path, _ = scene
    img = student_image(path)
    np.save(tmp_path / "img.npy", img)
    cli("diff", path, tmp_path / "img.npy", "-o", tmp_path / "out")
    png = np.asarray(PIL.open(tmp_path / "out" / "diff.png").convert("RGB"))
    picture = scantrace.diff(path, img).diff_image()
    assert picture.shape == (512, 512, 3) and picture.dtype == np.uint8
    # diff.png also outlines the worst 32 x 32 window in black: everything else is the picture.
    left = png[:512, :512]
    differ = (picture != left).any(axis=2)
    assert (left[differ] == 0).all() and 0 < differ.sum() <= 4 * 32
    assert (picture != 245).any(axis=2).sum() > 3 * 300  # the image's coloured differences


def test_diff_finds_a_global_mistake(scene):
    path, _ = scene
    img = scantrace.render(**scantrace.load_scene(path))[::-1]
    report = scantrace.diff(path, img)
    assert [g["kind"] for g in report.global_mistakes] == ["flipped_vertically"]
    assert not report.agrees


def test_diff_reads_read_only_and_strided_arrays_as_copies(scene):
    path, _ = scene
    img = student_image(path)
    ro = img.copy()
    ro.flags.writeable = False
    strided = np.zeros((512, 1024, 3))
    strided[:, ::2] = img
    big_endian = img.astype(">f8")
    expected = scantrace.diff(path, img).to_json()
    for other in (ro, strided[:, ::2], big_endian, np.asfortranarray(img)):
        assert scantrace.diff(path, other).to_json() == expected


@pytest.mark.parametrize("image, error, fragment", [
    (np.zeros((512, 512)), ValueError, "expected an array of shape (H, W, 3), got (512, 512)"),
    (np.zeros((512, 512, 4)), ValueError, "got (512, 512, 4)"),
    (np.zeros((0, 5, 3)), ValueError, "got (0, 5, 3)"),
    (np.zeros((512, 512, 3), bool), TypeError, "an integer dtype (values 0 .. 255), float32 or "
                                               "float64, got bool"),
    (np.full((512, 512, 3), 256, np.int32), ValueError, "image[0, 0]: an integer image holds "
                                                        "8-bit values 0 .. 255, got 256"),
    (np.full((512, 512, 3), np.nan), ValueError, "image[0, 0]: NaN and infinity are not allowed"),
    (np.full((512, 512, 3), 1e300), ValueError, "beyond float32's range"),
    ([[1, 2, 3]], TypeError, "expected an H x W x 3 numpy array or a path, got list"),
])
def test_diff_refuses_bad_images_in_one_line(scene, image, error, fragment):
    path, _ = scene
    with pytest.raises(error) as e:
        scantrace.diff(path, image)
    assert fragment in str(e.value) and "\n" not in str(e.value)


def test_diff_refuses_a_directory_and_bad_tolerances(scene, tmp_path):
    path, _ = scene
    img = scantrace.render(**scantrace.load_scene(path))
    with pytest.raises(ValueError, match="is a directory, not an image file"):
        scantrace.diff(path, tmp_path)
    for bad in (float("nan"), float("inf"), -0.1, 1.5):
        with pytest.raises(ValueError, match=r"tolerance: expected a difference per channel in \[0, 1\]"):
            scantrace.diff(path, img, tolerance=bad)
    with pytest.raises(TypeError, match="tolerance: expected a number, got str"):
        scantrace.diff(path, img, tolerance="0.1")


def test_scene_of_another_kind_is_a_type_error():
    with pytest.raises(TypeError, match="scene: expected a path, the dict load_scene returns"):
        scantrace.why(42, 0, 0)
    with pytest.raises(ValueError, match="scene: the dict has no 'depth'"):
        scantrace.why({"vertices": [], "faces": [], "vcolors": []}, 0, 0)


@pytest.mark.parametrize("x, y, error, fragment", [
    (512, 0, ValueError, "x: expected a pixel column, 0 .. width - 1 = 511, got 512"),
    (-1, 0, ValueError, "got -1"),
    (0, 2 ** 70, ValueError, "y: expected a pixel row"),
    (1.5, 0, TypeError, "x: expected an int (a pixel column), got float"),
    (0, float("nan"), TypeError, "y: expected an int (a pixel row), got float"),
])
def test_why_refuses_pixels_off_the_canvas(scene, x, y, error, fragment):
    path, _ = scene
    with pytest.raises(error) as e:
        scantrace.why(path, x, y)
    assert fragment in str(e.value)


def test_check_of_a_recorded_trace_is_consistent(scene, tmp_path):
    path, _ = scene
    t = scantrace.trace_scene(**scantrace.load_scene(path))
    result = scantrace.check(t)
    assert result.ok and bool(result) and result.problem is None
    assert result.triangles == len(t.triangles()) and result.events == len(t)
    # The command's own count of a file of the same trace.
    cli("trace", path, "-o", tmp_path / "t.jsonl")
    from_file = scantrace.check(tmp_path / "t.jsonl")
    assert from_file.ok and from_file.events == result.events
    assert from_file.scanlines == result.scanlines and from_file.edges == result.edges


def test_check_names_the_contradiction_as_the_command_does(scene, tmp_path):
    path, _ = scene
    cli("trace", path, "-o", tmp_path / "t.jsonl")
    lines = (tmp_path / "t.jsonl").read_text().splitlines()
    # Move an active edge's crossing by 1e-6 px: still sorted, finite and inside the span's
    # rounding, so only the exact recomputation of `check` can see it.
    for i, line in enumerate(lines):
        e = json.loads(line)
        if e.get("type") == "scanline" and e.get("span") and i > 10:
            e["active_edges"][0]["x"] += 1e-6
            lines[i] = json.dumps(e)
            break
    bad = tmp_path / "bad.jsonl"
    bad.write_text("\n".join(lines) + "\n")
    result = scantrace.check(bad)
    assert not result.ok and not bool(result)
    r = subprocess.run([SCANTRACE, "check", str(bad)], capture_output=True, text=True)
    assert r.returncode == 1
    assert result.problem in r.stderr
    assert result.problem.startswith(f"{bad}:{i + 1}: ")


def test_check_of_a_file_the_load_refuses_is_a_result_too(scene, tmp_path):
    path, _ = scene
    cli("trace", path, "-o", tmp_path / "t.jsonl")
    lines = (tmp_path / "t.jsonl").read_text().splitlines()
    del lines[5]  # a scanline missing: the cheap checks of every load see it
    (tmp_path / "bad.jsonl").write_text("\n".join(lines) + "\n")
    result = scantrace.check(tmp_path / "bad.jsonl")
    r = subprocess.run([SCANTRACE, "check", str(tmp_path / "bad.jsonl")], capture_output=True,
                       text=True)
    assert not result.ok and r.returncode == 1 and result.problem in r.stderr


def test_check_refuses_what_is_not_a_trace(tmp_path):
    with pytest.raises(TypeError, match="trace: expected a Trace or a path, got int"):
        scantrace.check(3)
    with pytest.raises(FileNotFoundError):
        scantrace.check(tmp_path / "missing.jsonl")
    with pytest.raises(ValueError, match="is a directory, not a trace"):
        scantrace.check(tmp_path)


def test_diff_of_a_png_file_is_the_commands_report(scene, tmp_path):
    pytest.importorskip("scantrace._scantrace_cv")
    path, _ = scene
    scantrace.write_png(student_image(path), tmp_path / "img.png")
    report = scantrace.diff(path, tmp_path / "img.png")
    assert json.loads(report.to_json()) == json.loads(cli("diff", path, tmp_path / "img.png",
                                                          "--json").stdout)
    assert not report.agrees
