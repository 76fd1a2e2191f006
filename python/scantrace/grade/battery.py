"""The tests a submission is graded on: vector_interp cases, the probes through f_shading and
g_shading, hidden scenes from the instructor's seed and the course scene, through render_img and
face by face. Builds the calls, runs them in one sandbox session, scores each test and gathers the
causes.
"""

import dataclasses
import functools

import numpy as np

import scantrace

from . import diagnose, fill_models, hidden, scoring, untrusted, whole_image
from .probes import (COLOURS, GOURAUD, PAIR_REGIONS, PAIRS, PAIRS_CORNER, PROBES,
                     SHARED_EDGE_FACES, SHARED_EDGE_SIZE)


@dataclasses.dataclass
class TestResult:
    name: str
    max_score: float
    score: float = 0.0
    output: str = ""
    visibility: str = "visible"
    verdict: str = ""       # the sandbox's verdict when the code did not run to the end
    probes: list = dataclasses.field(default_factory=list)   # ProbeOutcome of each probe
    key: str = ""           # the rubric key ("" for a deduction)
    weight: float | None = None   # the rubric's weight (None: a deduction, its own points)
    fraction: float = 0.0   # how much of the test is right, in [0, 1] (scoring.py)

    @property
    def status(self):
        return "passed" if self.score >= self.max_score else "failed"


@dataclasses.dataclass
class ProbeOutcome:
    """One probe of a probe test: whether it is in the assignment's domain (integer vertices, as
    the course's scene: `integer`), whether it passed, and if not the call's status and the first
    wrong row. Probes with integer False are "beyond the assignment"."""
    name: str
    integer: bool
    passed: bool
    status: str = "ok"          # the call's status: ok, error, timeout, memory, forbidden, crashed
    first_wrong_row: str = ""   # "row 7: expected 12..18, yours 11..18"


def _vi(p1, p2, v1, v2, coord, dim):
    """A vector_interp call as the course makes it: p1, p2 int64 arrays, V1, V2 float64 arrays of 3
    (or plain numbers: a scalar value), an int coord and dim 1 or 2. Students write
    `V1 + t * (V2 - V1)` on them, which fails on Python lists."""
    def value(v):
        return np.asarray(v, np.float64) if isinstance(v, (list, tuple)) else float(v)
    return (np.asarray(p1, np.int64), np.asarray(p2, np.int64), value(v1), value(v2), int(coord),
            int(dim))


def show_args(args):
    """The arguments of a vector_interp case as the student would type them."""
    return "(" + ", ".join(str(a.tolist()) if isinstance(a, np.ndarray) else repr(a)
                           for a in args) + ")"


# The course's vector_interp(p1, p2, V1, V2, coord, dim): (arguments, accepted answers).
VECTOR_CASES = (
    ("colour at the middle along x", _vi([0, 0], [10, 0], [1, 0, 0], [0, 0, 1], 5, 1), None),
    ("a quarter along y", _vi([2, 3], [8, 11], [0.0, 0.2, 1.0], [1.0, 0.6, 0.0], 5, 2), None),
    ("p1 after p2", _vi([10, 4], [2, 4], [0.5, 0.5, 0.5], [0.0, 1.0, 0.25], 4, 1), None),
    ("a scalar value", _vi([1, 1], [1, 9], 2.0, 10.0, 3, 2), None),
    ("at an endpoint", _vi([3, 7], [9, 1], [0.1, 0.2, 0.3], [0.9, 0.8, 0.7], 9, 1), None),
)
# Degenerate: equal coordinates along dim (V1, V2 or their midpoint accepted), a coordinate
# outside the segment (the line extended, or clamped to the nearer end).
VECTOR_DEGENERATE = (
    ("equal x with dim 1", _vi([4, 2], [4, 9], [1, 0, 0], [0, 0, 1], 4, 1), "equal"),
    ("equal points with dim 2", _vi([5, 5], [5, 5], [0.2, 0.4, 0.6], [0.6, 0.4, 0.2], 5, 2),
     "equal"),
    ("coord outside the segment", _vi([0, 0], [10, 0], [0, 0, 0], [1, 1, 1], 12, 1), "outside"),
)


def _accepted(args, kind):
    p1, p2, v1, v2, coord, dim = args
    v1, v2 = np.asarray(v1, float), np.asarray(v2, float)
    if kind == "equal":
        return [v1, v2, (v1 + v2) / 2]
    extended = scantrace.vector_interp(p1, p2, v1, v2, coord, dim)
    return [np.asarray(extended, float), v2 if abs(coord - p2[dim - 1]) < abs(coord - p1[dim - 1])
            else v1]


def course_arrays(scene):
    """The course's dtypes for a loaded scene: integer vertices when they are whole numbers."""
    vertices = np.asarray(scene["vertices"])
    if np.all(vertices == np.round(vertices)):
        vertices = vertices.astype(np.int64)
    return {"vertices": vertices, "faces": np.asarray(scene["faces"], np.int64),
            "vcolors": np.asarray(scene["vcolors"], np.float64),
            "depth": np.asarray(scene["depth"], np.float64).reshape(-1)}


def canvas(value, shape):
    """A student's canvas as float RGB in [0, 1] of `shape`, and the largest value when it came
    on a 0–255 scale (its painted pixels then divided by 255: whole_image.scale_255, diff's
    rule); or (None, an error message)."""
    if value.ndim != 3 or value.shape[2] != 3:
        return None, f"returned an array of shape {value.shape}, expected {shape}"
    if value.shape != tuple(shape) and value.shape[:2] != tuple(shape)[1::-1]:
        return None, f"returned an array of shape {value.shape}, expected {shape}"
    if not np.isfinite(value).all():
        return None, "returned NaN or infinite values"
    return whole_image.scale_255(value)


class Battery:
    def __init__(self, session, functions, rubric, scene=None, hidden_seed=None):
        self.session, self.functions, self.rubric = session, functions, rubric
        self.scene, self.hidden_seed = scene, hidden_seed
        self.calls, self.tests, self.causes = [], [], []
        self.beyond = set()     # calls on probes beyond the assignment (non-integer vertices)
        self.scaled = []        # (where, largest value) of each canvas on a 0–255 scale

    # ---- calls -------------------------------------------------------------------------------
    def _call(self, call_id, func, args, **extra):
        if func not in self.functions:
            return None
        self.calls.append({"id": call_id, "kind": "call", "func": func, "args": args, **extra})
        return call_id

    def _probe_call(self, func, probe):
        if not probe.integer:
            self.beyond.add(f"{func}_{probe.name}")
        args = [0, {"npy": self.session.input(probe.array)},
                {"npy": self.session.input(COLOURS)}]
        return self._call(f"{func}_{probe.name}", func, args, canvas=0,
                          canvas_shape=[*probe.size, 3])

    def _arg(self, value):
        """A call's argument: arrays go as .npy inputs (their dtype kept), numbers as JSON."""
        return {"npy": self.session.input(value)} if isinstance(value, np.ndarray) else value

    def _scene_inputs(self, scene):
        """The scene's arrays with the course's dtypes (int64 vertices and faces, float64
        colours and depths), whatever the scene was loaded or generated with: face by face the
        harness passes vertices[face] and vcolors[face] of these, as the course's render_img."""
        arrays, s = course_arrays(scene), self.session
        return {k: s.input(arrays[k]) for k in ("faces", "vertices", "vcolors", "depth")}

    def _scene_calls(self, label, scene, with_faces):
        names = self._scene_inputs(scene)
        order = np.argsort(-_mean_depth(scene), kind="stable")
        order_name = self.session.input(order.astype(np.int64))
        for shading in ("f", "g"):
            self._call(f"{label}_render_{shading}", "render_img",
                       [{"npy": names[k]} for k in ("faces", "vertices", "vcolors", "depth")]
                       + [shading], timeout=self.session.limits.call_seconds * 6)
            func = "f_shading" if shading == "f" else "g_shading"
            if with_faces and func in self.functions:
                self.calls.append({"id": f"{label}_faces_{shading}", "kind": "faces",
                                   "func": func, "canvas_shape": [512, 512, 3],
                                   "vertices": names["vertices"], "faces": names["faces"],
                                   "vcolors": names["vcolors"], "order": order_name,
                                   "timeout": self.session.limits.call_seconds * 6})

    def build(self):
        for i, (_, args, _) in enumerate(VECTOR_CASES + VECTOR_DEGENERATE):
            self._call(f"vi_{i}", "vector_interp", [self._arg(a) for a in args])
        for probe in PROBES:
            self._probe_call("f_shading", probe)
        for probe in GOURAUD:
            self._probe_call("g_shading", probe)
        names = self._scene_inputs(PAIRS)
        if "f_shading" in self.functions:
            self.calls.append({"id": "f_shading_shared_edge", "kind": "faces", "func": "f_shading",
                               "canvas_shape": [*SHARED_EDGE_SIZE, 3],
                               "vertices": names["vertices"], "faces": names["faces"],
                               "vcolors": names["vcolors"],
                               "order": self.session.input(np.array(SHARED_EDGE_FACES))})
        # Six faces: the plain call limit (a scene's is 6 times that).
        self._call("pairs_render_f", "render_img",
                   [{"npy": names[k]} for k in ("faces", "vertices", "vcolors", "depth")] + ["f"])
        self.hidden = hidden.scenes(self.hidden_seed, self.rubric.hidden_scenes) \
            if self.hidden_seed is not None else []
        for k, scene in enumerate(self.hidden):
            self._scene_calls(f"hidden{k + 1}", scene, with_faces=False)
        if self.scene is not None:
            self._scene_calls("course", self.scene, with_faces=True)
        for call in self.calls:
            # Another year's API: the harness calls the student's function through an adapter.
            adapter = getattr(self.functions.get(call["func"]), "adapter", None)
            if adapter:
                call["adapter"] = adapter

    def drop_unweighted(self):
        """Leaves out the calls of the tests the rubric weights 0: a test weighted 0 is not run.
        (The probes with non-integer vertices run with the flat probes, scored or not.)"""
        runs = self.rubric.runs
        self.calls = [c for c in self.calls if any(runs(k) for k in _call_keys(c["id"]))]
        if not runs("hidden_scene"):
            self.hidden = []
        self.course_tests = [k for k in ("course_scene", "course_faces")
                             if self.scene is not None and runs(k)]

    # ---- scoring -----------------------------------------------------------------------------
    def _canvas(self, value, shape, where):
        """canvas(), remembering where a canvas came on a 0–255 scale: it is rescaled to grade
        the rest, and the scale is named once (scaled_255), with the tests that showed it."""
        img, scale = canvas(value, shape)
        if img is None:
            return None, scale
        if scale is not None:
            self.scaled.append((where, scale))
        return img, ""

    def _scaled_255(self):
        if not self.scaled:
            return []
        where = list(dict.fromkeys(w for w, _ in self.scaled))   # a dozen at most
        return [diagnose.Cause(
            "scaled_255", 1.0,
            f"values up to {max(v for _, v in self.scaled):g} in {len(self.scaled)} returned "
            f"image(s): {'; '.join(where)}. The painted pixels were divided by 255 to grade the "
            "rest")]

    def grade(self, results):
        self.results = results
        self.causes += diagnose.diagnose_api(self.functions)
        # (scene label, shading): the reference and what goes with it, kept only while the
        # scene's tests use it (new 512 x 512 images kept alive cost page faults, not only memory).
        self._references = {}
        runs = self.rubric.runs
        if runs("vector_interp") or runs("vector_interp_degenerate"):
            self._vector_interp()
        if runs("probes_flat") or runs("probes_beyond"):
            self._probes_flat()
        if runs("probes_gouraud"):
            self._probes_gouraud()
        if runs("probes_pairs"):
            self._probes_pairs()
        for k, scene in enumerate(self.hidden):
            for shading in ("f", "g"):
                self._scene_test(f"hidden{k + 1}_render_{shading}", (f"hidden{k + 1}", scene),
                                 shading, f"Hidden scene {k + 1}: {_SHADING[shading]} "
                                 "(render_img)", "hidden_scene", painter=True)
                self._references.pop((f"hidden{k + 1}", shading), None)
            self._drop_scene(f"hidden{k + 1}")
        for shading in ("f", "g") if self.scene is not None else ():
            if "course_scene" in self._course_tests():
                self._scene_test(f"course_render_{shading}", ("course", self.scene), shading,
                                 f"Course scene: {_SHADING[shading]} (render_img)",
                                 "course_scene", painter=True)
            if "course_faces" in self._course_tests():
                self._scene_test(f"course_faces_{shading}", ("course", self.scene), shading,
                                 f"Course scene face by face: {_SHADING[shading]} "
                                 f"({'f' if shading == 'f' else 'g'}_shading in the painter's "
                                 "order)", "course_faces", painter=False)
            self._references.pop(("course", shading), None)
        self._drop_scene("course")
        self.causes += self._scaled_255()
        # A verdict on a probe beyond the assignment (a loop never reaching a float end) is in
        # that probe's line, not a cause: the course never passes such vertices.
        self.causes += diagnose.diagnose_verdicts(
            results, [c for c in self.calls if c["id"] not in self.beyond])
        scoring.allot(self.tests, self.rubric.total)
        return self.tests

    def _course_tests(self):
        return getattr(self, "course_tests", ("course_scene", "course_faces"))

    def _missing(self, name, key, func):
        self._add(name, key, 0.0, [f"No function `{func}` was found in the submission."],
                  verdict="missing")

    def _failed_call(self, result):
        detail = result.detail if len(result.detail) < 3000 else result.detail[:3000] + " …"
        return f"**{result.status}**: " + untrusted.md_block(detail)   # the student's text

    def _failure_lines(self, failed):
        """[(label, CallResult)] of failed calls as output lines, the calls failing the same way
        (the same status and last line: one TypeError on every probe) grouped into one line with
        their count and one traceback, not one traceback per call."""
        groups = {}
        for label, r in failed:
            last = r.detail.strip().splitlines()[-1] if r.detail.strip() else ""
            groups.setdefault((r.status, last), []).append((label, r))
        lines = []
        for members in groups.values():
            labels = [label for label, _ in members]
            head = labels[0] if len(labels) == 1 else (
                f"{len(labels)} calls failing the same way ({', '.join(labels[:5])}"
                + (", …" if len(labels) > 5 else "") + ")")
            lines.append(f"- {head}: {self._failed_call(members[0][1])}")
        return lines

    def _add(self, name, key, fraction, lines, visibility=None, verdict=""):
        """A test: its rubric key and the fraction of it that is right (scoring.allot turns the
        weights into points once every test is in). The causes found while grading it, not yet
        claimed by another test, are shown in its output (Cause.test)."""
        self.tests.append(TestResult(name, 0.0, 0.0, "\n".join(lines),
                                     visibility or self.rubric.visibility(key), verdict,
                                     key=key, weight=self.rubric.points(key),
                                     fraction=float(fraction)))
        for c in self.causes:
            if not c.test:
                c.test = name

    def _vector_interp(self):
        runs = self.rubric.runs
        if "vector_interp" not in self.functions:
            for name, key in (("vector_interp: ordinary cases", "vector_interp"),
                              ("vector_interp: degenerate cases", "vector_interp_degenerate")):
                if runs(key):
                    self._missing(name, key, "vector_interp")
            return
        if runs("vector_interp"):
            self._vector_ordinary()
        if runs("vector_interp_degenerate"):
            self._vector_degenerate()

    def _vector_ordinary(self):
        ok, lines, verdict, failed = 0, [], "", []
        for i, (text, args, _) in enumerate(VECTOR_CASES):
            r = self.results[f"vi_{i}"]
            expected = np.asarray(scantrace.vector_interp(*args), float)
            if r.status != "ok":
                failed.append((f"{text} `{show_args(args)}`", r))
                verdict = verdict or r.status
            elif r.value.shape == expected.shape and np.allclose(r.value, expected, atol=1e-6):
                ok += 1
            else:
                lines.append(f"- {text} `{show_args(args)}`: expected "
                             f"{np.round(expected, 4).tolist()}, yours "
                             f"{np.round(r.value, 4).tolist()}")
        self._add("vector_interp: ordinary cases", "vector_interp", ok / len(VECTOR_CASES),
                  [f"{ok} of {len(VECTOR_CASES)} cases right."] + self._failure_lines(failed)
                  + lines, verdict=verdict)
        # An exception the ordinary cases raise too is not the degenerate case's own failure.
        self._ordinary_failures = {r.detail.strip().splitlines()[-1] for _, r in failed
                                   if r.detail.strip()}

    def _vector_degenerate(self):
        ordinary = getattr(self, "_ordinary_failures", set())
        ok, lines, failures, verdict = 0, [], [], ""
        for j, (text, args, kind) in enumerate(VECTOR_DEGENERATE):
            r = self.results[f"vi_{len(VECTOR_CASES) + j}"]
            accepted = _accepted(args, kind)
            if r.status == "ok" and any(r.value.shape == a.shape and np.allclose(r.value, a)
                                        for a in accepted):
                ok += 1
                continue
            what = (self._failed_call(r) if r.status != "ok" else
                    f"returned {np.round(r.value, 4).tolist()}")
            lines.append(f"- {text} `{show_args(args)}`: {what}")
            if r.status not in ("ok", "error"):
                verdict = verdict or r.status   # a sandbox verdict, not a wrong formula
            elif kind == "equal" and (r.status == "ok" or not r.detail.strip()
                                      or r.detail.strip().splitlines()[-1] not in ordinary):
                failures.append((f"`vector_interp{show_args(args)}`",
                                 untrusted.md_code(r.detail.strip().splitlines()[-1])
                                 if r.status != "ok" and r.detail.strip() else what))
        self.causes += diagnose.diagnose_vector_interp(failures)
        self._add("vector_interp: degenerate cases", "vector_interp_degenerate",
                  ok / len(VECTOR_DEGENERATE),
                  [f"{ok} of {len(VECTOR_DEGENERATE)} cases right."] + lines, verdict=verdict)

    def _probe_images(self, func, probes):
        """The probes' canvases, and for the probes without one their outcome and lines."""
        images, lines, verdict, failed, outcomes = [], [], "", [], {}
        for probe in probes:
            r = self.results[f"{func}_{probe.name}"]
            if r.status != "ok":
                failed.append((f"probe `{probe.name}`{_domain(probe)}", r))
                outcomes[probe.name] = ProbeOutcome(probe.name, probe.integer, False, r.status)
                verdict = verdict or r.status
                continue
            img, error = self._canvas(r.value, (*probe.size, 3), f"the {func} probes")
            if img is None:
                lines.append(f"- probe `{probe.name}`: {error}")
                outcomes[probe.name] = ProbeOutcome(probe.name, probe.integer, False)
                continue
            if img.shape != (*probe.size, 3):
                img = img.transpose(1, 0, 2)
            images.append((probe, img))
        return self._untransposed(images), self._failure_lines(failed) + lines, verdict, outcomes

    def _untransposed(self, images):
        """Probe images written as img[x][y]: undone (the rest is graded) and named once."""
        pairs = [(p, img, diagnose.covered(img), expected_mask(p))
                 for p, img in images]
        straight = sum(int((got != want).sum()) for _, _, got, want in pairs)
        flipped = sum(int((got.T != want).sum()) for _, _, got, want in pairs)
        if straight == 0 or flipped > straight * 0.5:
            return images
        probe, _, got, want = max(pairs, key=lambda q: int((q[2] != q[3]).sum()))
        self._add_causes([diagnose.Cause(
            "transposed", 1 - flipped / straight,
            f"probe `{probe.name}`: {int((got != want).sum())} pixels differ from the expected "
            f"fill, {int((got.T != want).sum())} once your image is read as img[x][y]",
            picture_pixels=diagnose.fill_picture(got, want))], "")
        return [(p, np.ascontiguousarray(img.transpose(1, 0, 2))) for p, img in images]

    def _probes_flat(self):
        name = "Probes: flat fill (f_shading on single triangles and a shared edge)"
        if "f_shading" not in self.functions:
            return self._missing(name, "probes_flat", "f_shading")
        images, lines, verdict, outcomes = self._probe_images("f_shading", PROBES)
        mean = COLOURS.mean(axis=0)
        credit = {}
        for probe, img in images:
            expected = expected_mask(probe)
            got = diagnose.covered(img)
            colour_ok = not got.any() or np.abs(img[got] - mean).max() <= 2 / 255
            credit[probe.name] = scoring.flat_probe(expected, got, colour_ok)
            row = diagnose.first_wrong_row(got, expected)
            outcomes[probe.name] = ProbeOutcome(probe.name, probe.integer,
                                                not row and colour_ok, first_wrong_row=row)
            if credit[probe.name] < 1:
                lines.append(_flat_line(probe, expected, got, colour_ok, credit[probe.name], row))
        shared, shared_line = self._shared_edge_flat()
        self.causes += diagnose.diagnose_fill(
            [(p, diagnose.covered(img)) for p, img in images])
        self.causes += diagnose.diagnose_flat(images, COLOURS)
        scored = [p.name for p in PROBES if p.integer]
        beyond = [p.name for p in PROBES if not p.integer]
        mine = [l for l in lines if not any(f"probe `{b}`" in l for b in beyond)]
        theirs = [l for l in lines if l not in mine]
        values = [credit.get(p, 0.0) for p in scored] + [shared]
        head = (f"Credit {np.mean(values):.1%}: the mean over {len(values)} probes "
                f"({len(scored)} triangles with integer vertices, one at a time, and the pair of "
                f"faces sharing an edge, drawn one after the other); "
                f"{sum(v >= 1 for v in values)} of the {len(values)} are exactly right.")
        if self.rubric.runs("probes_beyond"):
            if self.rubric.runs("probes_flat"):
                self._add(name, "probes_flat", np.mean(values), [head] + mine + shared_line,
                          verdict=verdict)
            self._add("Probes beyond the assignment: non-integer vertices (f_shading)",
                      "probes_beyond", np.mean([credit.get(b, 0.0) for b in beyond]),
                      [f"{len(beyond)} probes whose vertices are not integers."] + theirs)
        elif self.rubric.runs("probes_flat"):
            note = ([f"Beyond the assignment, not scored ({len(beyond)} probes with non-integer "
                     "vertices; the course's vertices are integers):"] + theirs) if theirs else []
            self._add(name, "probes_flat", np.mean(values), [head] + mine + shared_line + note,
                      verdict=verdict)
        for test in self.tests:
            if test.key in ("probes_flat", "probes_beyond"):
                test.probes = [outcomes[p.name] for p in PROBES if p.name in outcomes]

    def _shared_edge_flat(self):
        """f_shading on the two faces of the pairs' shared edge, one after the other on one
        canvas, against the C++ fill's canvas: (credit, [the line saying where, if wrong])."""
        r = self.results.get("f_shading_shared_edge")
        what = "probe pair `shared_edge` (f_shading on two faces sharing an edge)"
        if r is None or r.status != "ok":
            return 0.0, [f"- {what}: {self._failed_call(r)}"] if r is not None else []
        img, error = self._canvas(r.value, (*SHARED_EDGE_SIZE, 3), "probe pair `shared_edge`")
        if img is None:
            return 0.0, [f"- {what}: {error}"]
        if any(c.id == "transposed" for c in self.causes):
            img = np.ascontiguousarray(img.transpose(1, 0, 2))   # undone as on the probes
        reference = np.ones((*SHARED_EDGE_SIZE, 3))
        for k in SHARED_EDGE_FACES:
            face = PAIRS["faces"][k]
            reference = scantrace.f_shading(reference, PAIRS["vertices"][face],
                                            PAIRS["vcolors"][face])
        credit, n_wrong, counted = scoring.image_credit(img, reference,
                                                        (reference == 1.0).all(axis=2))
        if n_wrong == 0:
            return 1.0, []
        rows = np.flatnonzero((diagnose.channel_error(img, reference) > 1.5 / 255).any(axis=1))
        return credit, [f"- {what}, credit {credit:.0%}: {n_wrong} of its {counted} pixels differ "
                        f"from the expected fill, first on row {int(rows[0])} (each pixel of the "
                        "shared edge belongs to one face only: the one whose left edge it is)"]

    def _probes_gouraud(self):
        name = "Probes: Gouraud fill (g_shading on single triangles)"
        if "g_shading" not in self.functions:
            return self._missing(name, "probes_gouraud", "g_shading")
        images, lines, verdict, outcomes = self._probe_images("g_shading", GOURAUD)
        credit = {}
        for probe, img in images:
            ref = scantrace.g_shading(np.ones((*probe.size, 3)), probe.array, COLOURS)
            expected, got = diagnose.covered(ref), diagnose.covered(img)
            colour_right = diagnose.channel_error(img, ref) <= 0.02
            credit[probe.name] = scoring.gouraud_probe(expected, got, colour_right)
            row = diagnose.first_wrong_row(got, expected)
            outcomes[probe.name] = ProbeOutcome(probe.name, probe.integer,
                                                credit[probe.name] >= 1, first_wrong_row=row)
            if credit[probe.name] < 1:
                both = expected & got
                error = float(np.abs(img[both] - ref[both]).max()) if both.any() else 0.0
                lines.append(f"- probe `{probe.name}` ({probe.what}), credit "
                             f"{credit[probe.name]:.0%}: {int((expected != got).sum())} of "
                             f"{int((expected | got).sum())} pixels filled differently, "
                             f"{int((both & ~colour_right).sum())} with a colour off by more "
                             f"than 0.02 (the largest {error:.3f})" + (f"; {row}" if row else ""))
        self.causes += diagnose.diagnose_gouraud(images, COLOURS, scantrace.g_shading)
        values = [credit.get(p.name, 0.0) for p in GOURAUD]
        self._add(name, "probes_gouraud", np.mean(values),
                  [f"Credit {np.mean(values):.1%}: the mean over {len(values)} probes, each the "
                   "share of its pixels filled and coloured right (a pixel filled with a wrong "
                   f"colour counts half); {sum(v >= 1 for v in values)} of the {len(values)} are "
                   "exactly right."] + lines, verdict=verdict)
        self.tests[-1].probes = [outcomes[p.name] for p in GOURAUD if p.name in outcomes]

    def _probes_pairs(self):
        """render_img on pairs of faces (probes.PAIRS): a shared edge, tied depths, distinct
        depths; each pair's region compared with the reference, the order causes diagnosed on
        the pixels each order changes (as on the hidden scenes), with a picture."""
        name = "Probes: pairs of faces (render_img: a shared edge, tied and distinct depths)"
        if "render_img" not in self.functions:
            return self._missing(name, "probes_pairs", "render_img")
        r = self.results["pairs_render_f"]
        if r.status != "ok":
            return self._add(name, "probes_pairs", 0.0, [self._failed_call(r)], verdict=r.status)
        img, error = self._canvas(r.value, (512, 512, 3), "render_img on the probe pairs")
        if img is None:
            return self._add(name, "probes_pairs", 0.0, [f"`render_img` {error}."])
        # The pairs lie in the canvas's top-left corner: compared there only (a square, so a
        # transposed canvas is still the corner transposed), a tenth of the grader's time.
        refs = _pairs_references()
        fixed, causes = diagnose.diagnose_image(
            np.ascontiguousarray(img[:PAIRS_CORNER, :PAIRS_CORNER]), refs["reference"],
            refs["uncovered"], refs["alternatives"], refs["faces"])
        self._add_causes(causes, "probe scene `pairs` (render_img, flat): ")
        values, lines = [], []
        for (pair, what, faces, region), counts in zip(PAIR_REGIONS, refs["counted"]):
            credit, n_wrong, counted = scoring.image_credit(
                fixed[region], refs["reference"][region], ~counts[region])
            values.append(credit)
            if n_wrong:
                error = diagnose.channel_error(fixed[region], refs["reference"][region])
                rows = np.flatnonzero((error > scoring.CLOSE).any(axis=1))
                lines.append(f"- pair `{pair}` ({what}, faces {faces[0]} and {faces[1]}), credit "
                             f"{credit:.0%}: {n_wrong} of its {counted} pixels differ, first on "
                             f"row {int(rows[0]) + (region[0].start or 0)}")
        self._add(name, "probes_pairs", np.mean(values),
                  [f"Credit {np.mean(values):.1%}: the mean over {len(values)} pairs, each the "
                   "share of its pixels drawn right (of two overlapping faces, the pixels they "
                   f"share: what the order decides); {sum(v >= 1 for v in values)} of the "
                   f"{len(values)} are exactly right."] + lines)

    def _scene_test(self, call_id, labelled, shading, name, key, painter):
        func = "render_img" if painter else ("f_shading" if shading == "f" else "g_shading")
        if func not in self.functions:
            return self._missing(name, key, func)
        r = self.results[call_id]
        if r.status != "ok":
            return self._add(name, key, 0.0, [self._failed_call(r)], verdict=r.status)
        scales = len(self.scaled)
        img, error = self._canvas(r.value, (512, 512, 3), name)
        if img is None:
            return self._add(name, key, 0.0, [f"`{func}` {error}."])
        refs = self._scene_references(*labelled, shading, painter)
        # The whole-image mistakes are undone in every image test, face by face included (the
        # order's alternatives only where the student's own render_img chose the order).
        fixed, causes = diagnose.diagnose_image(img, refs["reference"], refs["uncovered"],
                                                refs.pop("alternatives") if painter else {},
                                                refs.pop("faces") if painter else None)
        self._add_causes(causes, f"{name}: ")
        credit, n_wrong, counted = scoring.image_credit(fixed, refs["reference"],
                                                        refs["uncovered"])
        undone = [c.id for c in causes if c.id in diagnose.WHOLE_IMAGE_MISTAKES]
        if len(self.scaled) > scales:
            undone.append("the 0–255 range of the painted pixels")
        self._add(name, key, credit,
                  [f"Credit {credit:.1%}: {counted - n_wrong:,} of the {counted:,} pixels that "
                   "a face covers (in the reference or yours) are right"
                   + (f" (after undoing {', '.join(undone)})" if undone else "") + "."])

    def _scene_references(self, label, scene, shading, painter):
        """The reference of a scene and shading, the pixels no face covers, and (for render_img)
        the images of the painter's-order mistakes: rendered once per submission, whichever tests
        use them."""
        refs = self._references.setdefault((label, shading), {})
        if "reference" not in refs:
            refs["reference"] = scantrace.render_img(scene["faces"], scene["vertices"],
                                                     scene["vcolors"], scene["depth"], shading)
            # The pixels no face covers are the same in both shadings: found once per scene.
            if (label, "uncovered") not in self._references:
                self._references[(label, "uncovered")] = _uncovered(scene, shading,
                                                                    refs["reference"])
            refs["uncovered"] = self._references[(label, "uncovered")]
        if painter and "alternatives" not in refs:
            refs["alternatives"] = _painter_alternatives(scene, shading)
            # Which face each pixel shows depends on the geometry and depths alone, not on the
            # shading: found once per scene too.
            if (label, "faces") not in self._references:
                self._references[(label, "faces")] = _painter_faces(scene)
            refs["faces"] = self._references[(label, "faces")]
        return refs

    def _drop_scene(self, label):
        """Forgets a scene's per-scene images once both its shadings are graded."""
        for what in ("uncovered", "faces"):
            self._references.pop((label, what), None)

    def _add_causes(self, causes, prefix):
        for c in causes:
            if not any(k.id == c.id for k in self.causes):
                c.evidence = prefix + c.evidence
                self.causes.append(c)


_SHADING = {"f": "flat", "g": "Gouraud"}


def _domain(probe):
    """Marks a probe outside the assignment's domain (the course's vertices are integers)."""
    return "" if probe.integer else " (beyond the assignment: non-integer vertices)"


def _mean_depth(scene):
    return np.asarray(scene["depth"], np.float64).reshape(-1)[scene["faces"]].mean(axis=1)


def _uncovered(scene, shading, white):
    black = scantrace.render(scene["vertices"], scene["faces"], scene["vcolors"], scene["depth"],
                             shading=shading, background=(0.0, 0.0, 0.0))
    w, b = white == 1.0, black == 0.0
    return w[..., 0] & w[..., 1] & w[..., 2] & b[..., 0] & b[..., 1] & b[..., 2]


def _painter_alternatives(scene, shading):
    """The scene painted nearest first (a reversed sort), and with ties of mean depth painted in
    reverse face order (an unstable or reversed argsort)."""
    f, v, c, d = scene["faces"], scene["vertices"], scene["vcolors"], scene["depth"]
    reversed_order = scantrace.render_img(f, v, c, -np.asarray(d, np.float64), shading)
    ties_reversed = scantrace.render_img(f[::-1].copy(), v, c, d, shading)
    return {"order_reversed": reversed_order, "order_unstable_on_ties": ties_reversed}


@functools.lru_cache(maxsize=None)
def expected_mask(probe):
    """A probe's exact fill (fill_models.correct, in exact arithmetic: the grader's slowest
    Python), computed once per grading process: the probes are the same for every submission.
    Read-only, as it is shared."""
    mask = fill_models.correct(probe.array, probe.size)
    mask.flags.writeable = False
    return mask


def warm_up():
    """Computes what is the same for every submission (each probe's exact fill, the pairs
    probe's references) in this process: a class's parent calls it before forking its workers,
    which then share it instead of computing it once each."""
    for probe in PROBES + GOURAUD:
        expected_mask(probe)
        fill_models.correct(probe.array, probe.size)
    _pairs_references()


@functools.lru_cache(maxsize=1)
def _pairs_references():
    """The pairs probe's reference, uncovered pixels and painter's-order mistakes, in its corner:
    the same for every submission, so computed once per grading process."""
    corner = (slice(0, PAIRS_CORNER), slice(0, PAIRS_CORNER))
    reference = scantrace.render_img(PAIRS["faces"], PAIRS["vertices"], PAIRS["vcolors"],
                                     PAIRS["depth"], "f")
    uncovered = _uncovered(PAIRS, "f", reference)[corner]
    # What each pair is scored on: where its two faces overlap, the pixels the painter's order
    # decides (a reversed order spoils all of them, not a sliver of the pair's area); two faces
    # that only share an edge test the fill rule, on all their pixels.
    counted = []
    for _, _, faces, _ in PAIR_REGIONS:
        a, b = (fill_models.correct(PAIRS["vertices"][PAIRS["faces"][f]].astype(float),
                                    (PAIRS_CORNER, PAIRS_CORNER)) for f in faces)
        counted.append(a & b if (a & b).any() else ~uncovered)
    return {"reference": reference[corner], "uncovered": uncovered, "counted": counted,
            "alternatives": {k: v[corner] for k, v in _painter_alternatives(PAIRS, "f").items()},
            "faces": {k: v[corner] for k, v in _painter_faces(PAIRS).items()}}


def _flat_line(probe, expected, got, colour_ok, credit, row):
    """A flat probe not exactly right: its rows right, one pixel off and wrong, the first wrong
    row as a reader checks it by hand (diagnose.first_wrong_row), the colour, and its credit."""
    right, near, counted = scoring.fill_rows(expected, got)
    return (f"- probe `{probe.name}` ({probe.what}){_domain(probe)}, credit {credit:.0%}: "
            f"{right} of its {counted} rows right, {near} one pixel off at an end, "
            f"{counted - right - near} wrong" + (f"; {row}" if row else "")
            + ("; wrong colour" if not colour_ok else ""))


def _call_keys(call_id):
    """The rubric keys of the tests a call serves (a call is made when one of them runs)."""
    if call_id.startswith("vi_"):
        degenerate = int(call_id[3:]) >= len(VECTOR_CASES)
        return ("vector_interp_degenerate",) if degenerate else ("vector_interp",)
    if call_id.startswith("f_shading_"):
        return ("probes_flat", "probes_beyond")
    prefixes = (("g_shading_", "probes_gouraud"), ("pairs_", "probes_pairs"),
                ("hidden", "hidden_scene"), ("course_render_", "course_scene"),
                ("course_faces_", "course_faces"))
    return tuple(k for p, k in prefixes if call_id.startswith(p)) or ("probes_flat",)


def face_ids(faces, vertices, depth):
    """Which face each pixel of render_img(faces, vertices, ·, depth) shows (its row in
    `faces`; -1: none): the scene rendered flat with each face on vertices of its own, coloured
    by its row number in base 255 (a face's flat colour is the mean of three equal colours). The
    mean depths, hence the painter's order and its ties, are the scene's own."""
    faces = np.asarray(faces, np.int64)
    n = len(faces)
    code = np.arange(1, n + 1)
    colour = np.stack([code % 255, code // 255 % 255, code // 255 ** 2], axis=1) / 254.0
    own = np.arange(3 * n, dtype=np.int64).reshape(n, 3)
    img = scantrace.render_img(own, np.asarray(vertices)[faces].reshape(-1, 2),
                               np.repeat(colour, 3, axis=0),
                               np.asarray(depth, np.float64).reshape(-1)[faces].reshape(-1), "f")
    digits = np.rint(img * 254.0).astype(np.int64)
    ids = digits[..., 0] + 255 * digits[..., 1] + 255 ** 2 * digits[..., 2] - 1
    ids[ids >= n] = -1          # white, 254 in every digit: no face
    return ids


def _painter_faces(scene):
    """face_ids() of the reference and of each of _painter_alternatives()' orders."""
    f, v, d = scene["faces"], scene["vertices"], np.asarray(scene["depth"], np.float64)
    n = len(f)
    ties = face_ids(f[::-1].copy(), v, d)
    return {"reference": face_ids(f, v, d), "order_reversed": face_ids(f, v, -d),
            "order_unstable_on_ties": np.where(ties >= 0, n - 1 - ties, -1)}
