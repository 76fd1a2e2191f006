"""From the student's results to causes: each candidate mistake is a model (fill_models.py for the
fill, a permutation or a re-ordered render for colours and order); a cause is the model that
explains what the submission did where the correct model does not.
"""

import itertools
import math

import numpy as np

from . import fill_models, whole_image
from .causes import CONFIDENCE, Cause  # noqa: F401 - Cause is used by battery too

WHITE_TOLERANCE = 1e-6


def covered(img):
    """The pixels a fill wrote on a white canvas."""
    return np.any(np.abs(img - 1.0) > WHITE_TOLERANCE, axis=2)


def _rows_differing(a, b):
    return set(np.flatnonzero((a != b).any(axis=1)).tolist())


def _fmt_span(spans, y):
    runs = spans.get(y, [])
    if not runs:
        return "nothing"
    return ", ".join(f"{a}…{b - 1}" for a, b in runs)


def _runs_text(row):
    """A row of a mask as its runs of columns: "12..18", "3..5, 9..12" or "nothing"."""
    padded = np.concatenate(([False], row, [False])).astype(np.int8)
    d = np.flatnonzero(np.diff(padded))
    return ", ".join(f"{a}..{b - 1}" for a, b in zip(d[::2], d[1::2])) or "nothing"


def first_wrong_row(student, expected):
    """The first row where the student's mask differs from the expected one, as a reader checks
    it by hand: "row 7: expected 12..18, yours 11..18" ("" when the masks are equal)."""
    rows = np.flatnonzero((student != expected).any(axis=1))
    if not len(rows):
        return ""
    y = int(rows[0])
    return f"row {y}: expected {_runs_text(expected[y])}, yours {_runs_text(student[y])}"


def _fill_evidence(probe, student, model_mask, correct):
    """The first row where the submission differs from the correct fill and the model explains
    it: the row, the crossings, the span expected and the student's."""
    rows = sorted(r for r in _rows_differing(student, correct)
                  if (student[r] == model_mask[r]).all())
    y = rows[0] if rows else sorted(_rows_differing(student, correct))[0]
    ends = fill_models._span_ends(fill_models._exact(probe.array), fill_models.Fraction(y))
    crossing = (f" (x_L = {float(ends[0]):.4g}, x_R = {float(ends[1]):.4g})" if ends else "")
    tri = " ".join(f"({x:g}, {yy:g})" for x, yy in probe.vertices)
    exp, got = fill_models.row_spans(correct), fill_models.row_spans(student)
    return (f"probe `{probe.name}` ({probe.what}: {tri}), row {y}{crossing}: expected columns "
            f"{_fmt_span(exp, y)}, yours {_fmt_span(got, y)}"), y


def fill_picture(student, correct, scale=6):
    """A small picture: grey where both fill, red where only the reference fills, blue where only
    the submission does."""
    img = np.ones(correct.shape + (3,))
    img[correct & student] = (0.6, 0.6, 0.6)
    img[correct & ~student] = (0.9, 0.1, 0.1)
    img[~correct & student] = (0.1, 0.3, 0.95)
    return np.kron(img, np.ones((scale, scale, 1)))


IMAGE_LEGEND = "left: expected; right: yours (the region where the pixels differ, magnified)"


def image_picture(student, reference, mask, size=32, scale=6):
    """A small picture of an image-level cause: the reference and the student's image side by
    side, cropped to the bounding box of `mask` (at most size x size from its top-left)."""
    ys, xs = np.nonzero(mask)
    if len(ys) == 0:
        return None
    y0, x0 = int(ys.min()), int(xs.min())
    y1, x1 = min(int(ys.max()) + 1, y0 + size), min(int(xs.max()) + 1, x0 + size)
    # Three pixels of context around the region.
    y0, x0 = max(0, y0 - 3), max(0, x0 - 3)
    y1, x1 = min(y1 + 3, mask.shape[0]), min(x1 + 3, mask.shape[1])
    expected, got = reference[y0:y1, x0:x1], np.clip(student[y0:y1, x0:x1], 0, 1)
    gap = np.full((y1 - y0, 1, 3), 0.5)
    return np.kron(np.concatenate([expected, gap, got], axis=1), np.ones((scale, scale, 1)))


def _drift_signature(probe, student, correct):
    """True when every differing row is one where an edge crosses a pixel centre exactly, after
    the edge's first row, and the span end there is off by one: the trace of accumulated x."""
    tri = fill_models._exact(probe.array)
    diff_rows = _rows_differing(student, correct)
    if not diff_rows:
        return True
    for y in diff_rows:
        active = fill_models._active(fill_models._edges(tri), fill_models.Fraction(y))
        on_centre = [e for e in active
                     if fill_models._x_at(e, y).denominator == 1 and y > math.ceil(e[0][1])]
        if not on_centre or (student[y] != correct[y]).sum() != 1:
            return False
    return True


def _candidates(plain):
    """Every fill model as (cause keys, {probe name: its rows}): the compositions of
    fill_models (span ends × rows × edge stepping × vertex rounding, the one-mistake models
    among them) and the whole-face and canvas models, which compose with nothing."""
    composers = {p.name: fill_models.Composer(p.array, p.size) for p, _ in plain}
    for composition in fill_models.COMPOSITIONS:
        yield (fill_models.causes_of(composition),
               {p.name: composers[p.name].rows(composition) for p, _ in plain},
               lambda p, c=composition: composers[p.name].mask(c))
    for key in (k for k in fill_models.MODELS if k[0] in ("horizontal_edge_skipped",
                                                          "canvas_border_clipped")):
        model = fill_models.MODELS[key]
        yield ([key], {p.name: fill_models.row_spans(model(p.array, p.size)) for p, _ in plain},
               lambda p, m=model: m(p.array, p.size))


def _explains(results, wrong):
    """How well each model explains the student's rows, best first: (rows it gets wrong on
    integer probes, on the others, how many causes it names, keys, mask function). The integer
    probes — the assignment's domain — rank first; the non-integer ones only break ties."""
    students = {p.name: fill_models.row_spans(m) for p, m in results}
    integer = {p.name: p.integer for p, _ in results}
    ranked = []
    for keys, rows, mask in _candidates(results):
        bad = [0, 0]
        for name, model in rows.items():
            student = students[name]
            n = sum(model.get(y) != student.get(y) for y in set(model) | set(student))
            bad[0 if integer[name] else 1] += n
        ranked.append((bad[0], bad[1], len({k[0] for k in keys}), keys, mask))
        if not bad[0] and bad[1] <= wrong[1] * (1 - CONFIDENCE) and len(keys) == 1:
            break      # a one-mistake model explains the assignment's rows: no need to compose
    ranked.sort(key=lambda r: r[:3])
    return ranked


def diagnose_fill(results):
    """results: [(probe, student mask)] from f_shading on blank canvases. Returns causes: the
    fill model explaining most of the student's wrong rows, each of its causes named when it
    explains at least CONFIDENCE of them on the integer probes (the non-integer ones, beyond the
    assignment, decide only when every integer probe is right)."""
    plain = [(p, m) for p, m in results if not fill_models.degenerate(p.array)]
    correct = {p.name: fill_models.correct(p.array, p.size) for p, _ in results}
    wrong = [sum(len(_rows_differing(m, correct[p.name])) for p, m in plain if p.integer == i)
             for i in (True, False)]
    causes = []
    if any(wrong):
        ranked = _explains(plain, wrong)
        best = ranked[0][:3]
        domain = 0 if wrong[0] else 1
        confidence = 1 - best[domain] / wrong[domain]
        named = [r for r in ranked if r[:3] == best] if confidence >= CONFIDENCE else []
        if not named and all(_drift_signature(p, m, correct[p.name]) for p, m in plain
                             if p.integer or not wrong[0]):
            # Drift depends on how the student accumulated: its signature is enough.
            named = [r for r in ranked if r[3] == [("float_drift", "")]][:1]
            confidence = CONFIDENCE
        for _, _, _, keys, mask_of in named:
            causes += _fill_causes(plain, correct, keys, mask_of, confidence, causes)
    drawn = [(p, m) for p, m in results if fill_models.degenerate(p.array) and m.any()]
    if drawn:
        p, m = drawn[0]
        spans = fill_models.row_spans(m)
        causes.append(Cause("degenerate_drawn", 1.0,
                            f"probe `{p.name}` ({p.what}: "
                            + " ".join(f"({x:g}, {y:g})" for x, y in p.vertices)
                            + f"), row {min(spans)}: expected columns "
                            f"nothing, yours {_fmt_span(spans, min(spans))}"
                            f" ({int(m.sum())} pixels in all)",
                            picture_pixels=fill_picture(m, correct[p.name])))
    return causes


def _fill_causes(plain, correct, keys, mask_of, confidence, named):
    """A cause for each key of a model not yet named, its evidence a probe where the model draws
    exactly what the student drew (an integer probe first)."""
    candidates = sorted(((p, m) for p, m in plain if _rows_differing(m, correct[p.name])),
                        key=lambda q: not q[0].integer)
    exact = [(p, m) for p, m in candidates if (m == mask_of(p)).all()]
    probe, mask = (exact or candidates)[0]
    text, _ = _fill_evidence(probe, mask, mask_of(probe), correct[probe.name])
    # Rounding the vertices is harmless on the course's integer vertices: not a cause, but it
    # explains the non-integer probes (beyond the assignment), so it is said in the evidence.
    mistakes = [k for k in keys if k[0] != "vertices_rounded"]
    if len(mistakes) > 1:
        text += " (" + " and ".join(f"`{k[0]}`" for k in mistakes) + " together explain it)"
    if len(mistakes) < len(keys):
        text += ("; your vertices are rounded to whole pixels first (int(round(x))), which "
                 "only the non-integer probes, beyond the assignment, show")
    return [Cause(cause_id, confidence, text, detail=variant or "",
                  picture_pixels=fill_picture(mask, correct[probe.name]))
            for cause_id, variant in mistakes if not any(c.id == cause_id for c in named)]


def key_is_drift(cause_id):
    return cause_id == "float_drift"


def _describe_colour(c):
    return "(" + ", ".join(f"{v:.3g}" for v in c) + ")"


def diagnose_flat(results, colours):
    """results: [(probe, student image)] of f_shading; the colour is the mean of `colours`."""
    mean = colours.mean(axis=0)
    for probe, img in results:
        both = covered(img) & fill_models.correct(probe.array, probe.size)
        if not both.any():
            continue
        got = np.median(img[both], axis=0)
        if np.abs(got - mean).max() <= 2 / 255:
            continue
        what = f"the colour {_describe_colour(got)}"
        for k in range(3):
            if np.abs(got - colours[k]).max() <= 2 / 255:
                what = f"the colour of vertex {k} {_describe_colour(got)}"
        if np.abs(got - np.median(colours, axis=0)).max() <= 2 / 255:
            what = f"the per-channel median {_describe_colour(got)}"
        expected = np.ones(img.shape)
        expected[fill_models.correct(probe.array, probe.size)] = mean
        return [Cause("flat_colour_not_mean", 1.0,
                      f"probe `{probe.name}`: expected the mean {_describe_colour(mean)}, yours "
                      f"{_describe_colour(got)}", detail=what,
                      picture_pixels=image_picture(img, expected, np.ones(both.shape, bool)),
                      legend=IMAGE_LEGEND)]
    return []


def _colour_error(student, reference, mask):
    return float(np.abs(student[mask] - reference[mask]).mean()) if mask.any() else 0.0


def diagnose_gouraud(results, colours, g_shading):
    """results: [(probe, student image)] of g_shading; g_shading(img, vertices, vcolors) the
    reference. Tests every fixed permutation of the vertex colours and the colours left in place
    while the vertices are sorted by y."""
    perms = [p for p in itertools.permutations(range(3))]
    errors = {p: [] for p in perms}
    errors["sorted"] = []
    for probe, img in results:
        blank = np.ones(probe.size + (3,))
        mask = covered(img) & fill_models.correct(probe.array, probe.size)
        for p in perms:
            ref = g_shading(blank.copy(), probe.array, colours[list(p)])
            errors[p].append(_colour_error(img, ref, mask))
        order = np.argsort(probe.array[:, 1], kind="stable")
        ref = g_shading(blank.copy(), probe.array[order], colours)
        errors["sorted"].append(_colour_error(img, ref, mask))
    worst = {k: max(v) if v else 0.0 for k, v in errors.items()}
    if worst[(0, 1, 2)] <= 0.01:
        return []
    best = min(worst, key=worst.get)
    if worst[best] > 0.01:
        return []
    k = int(np.argmax(errors[(0, 1, 2)]))
    probe, img = results[k]
    evidence = (f"probe `{probe.name}`: mean colour error {errors[(0, 1, 2)][k]:.3f} against "
                f"the correct fill, {errors[best][k]:.4f} against the model")
    picture = image_picture(img, g_shading(np.ones(probe.size + (3,)), probe.array, colours),
                            np.ones(probe.size, bool))
    if best == "sorted":
        return [Cause("colours_paired_after_sort", 1.0, evidence, picture_pixels=picture,
                      legend=IMAGE_LEGEND)]
    detail = ", ".join(f"vertex {i} gets the colour of vertex {best[i]}"
                       for i in range(3) if best[i] != i)
    return [Cause("gouraud_weights_permuted", 1.0, evidence, detail=detail,
                  picture_pixels=picture, legend=IMAGE_LEGEND)]


def channel_error(a, b):
    """Per pixel, the largest channel difference |a − b| of two H x W x 3 images. (A numpy
    reduction over the 3 channels is several times slower than two maxima of slices: it was most
    of the grader's own time on 512² scenes.)"""
    d = np.subtract(a, b)
    np.abs(d, out=d)          # in place: a third of the time of np.abs(a - b) on 512 x 512
    error = np.maximum(d[..., 0], d[..., 1])
    return np.maximum(error, d[..., 2], out=error)


def image_mismatch(a, b):
    """The fraction of pixels whose colour differs by more than 1.5/255 in some channel."""
    wrong = channel_error(a, b) > 1.5 / 255
    return np.count_nonzero(wrong) / wrong.size


# The whole-image mistakes whole_image.py finds and undoes (the 0–255 scale is undone earlier,
# on every canvas: battery.canvas).
WHOLE_IMAGE_MISTAKES = ("transposed", "flipped_vertically", "flipped_horizontally", "bgr",
                        "background")


def undo_global(student, reference, uncovered):
    """The whole-image mistakes undone *together*, by diff's C++ (whole_image.py): the transform
    (transposed, flipped, BGR) is chosen on the pixels the reference's faces cover, where a wrong
    background cannot weigh, and the background on the pixels no face covers, once the transform
    is undone; each is undone only when named. Returns (image, causes), the image `student`
    itself when nothing was named."""
    fixed, causes, _ = whole_image.whole_image_mistakes(student, reference, uncovered)
    if not causes:
        return student, []
    same_shape = student.shape == reference.shape
    for c in causes:
        if c.id == "background":
            # The pixels no face covers that the undo changed: the background as painted.
            shown = uncovered & (channel_error(fixed, student) > 0) if same_shape else uncovered
        else:
            shown = channel_error(student, reference) > 1.5 / 255 if same_shape else None
        if shown is not None:
            c.picture_pixels, c.legend = image_picture(student, reference, shown), IMAGE_LEGEND
    return fixed, causes


def _never_drawn(student, shown):
    """The faces the student's image shows nowhere: for each face, the share of its pixels in
    each of `shown` [(image, face ids, -1 for none)] where the student's image has that image's
    colour; below a tenth in every one, the face is taken as never drawn (a skipped face), in
    whichever order it was painted. Returns a lookup by face id (its last entry, id -1: False)."""
    n = max(int(ids.max()) for _, ids in shown) + 1
    best = np.zeros(max(n, 0))
    for image, ids in shown:
        face = ids >= 0
        same = channel_error(student, image)[face] <= 1.5 / 255
        seen = np.bincount(ids[face], minlength=n)
        best = np.maximum(best, np.bincount(ids[face], weights=same, minlength=n)
                          / np.maximum(seen, 1))
    return np.append(best < 0.1, False)


def diagnose_image(student, reference, uncovered, alternatives, faces=None):
    """Global mistakes of a rendered image, undone together so the rest can be graded (a
    transpose, BGR channels, a background colour: undo_global); then the painter's order, from
    `alternatives` {cause id: the reference rendered with that mistake}. `faces` {"reference" or
    a cause id: which face each pixel of that image shows, -1 for none} keeps the faces the
    student never draws out of the order's pixels. Returns (image, causes)."""
    base = image_mismatch(student, reference)
    causes = []
    if base > 0:
        student, causes = undo_global(student, reference, uncovered)
        base = image_mismatch(student, reference)
    for cause_id, alt in alternatives.items():
        # Only the pixels this order changes decide (a wrong fill elsewhere does not blur it).
        deciding = channel_error(alt, reference) > 1.5 / 255
        if base == 0 or not deciding.any():
            continue
        skipped = 0
        if faces:
            # A face never drawn (skipped for its horizontal edge, say) uncovers what lies under
            # it, which is what the other order shows there: missing, not reordered.
            ids = (faces["reference"], faces[cause_id])
            never = _never_drawn(student, [(reference, ids[0]), (alt, ids[1])])
            on_skipped = deciding & (never[ids[0]] | never[ids[1]])
            skipped = int(on_skipped.sum())
            deciding &= ~on_skipped
        close = 1.5 / 255
        as_alt = int((channel_error(student, alt)[deciding] <= close).sum())
        as_ref = int((channel_error(student, reference)[deciding] <= close).sum())
        if deciding.any() and as_alt >= 0.5 * deciding.sum() and as_alt > 2 * as_ref:
            causes.append(Cause(cause_id, as_alt / (as_alt + as_ref),
                                f"of the {int(deciding.sum())} pixels this order changes, yours "
                                f"has {as_alt} as painted in this order and {as_ref} as in the "
                                "correct one" + (f" ({skipped} more lie on faces yours never "
                                                 "draws: not counted)" if skipped else ""),
                                picture_pixels=image_picture(student, reference, deciding),
                                legend=IMAGE_LEGEND))
    return student, causes


def diagnose_vector_interp(failures):
    """failures: [(case text, what happened)] of the degenerate vector_interp cases."""
    if not failures:
        return []
    text, what = failures[0]
    return [Cause("vector_interp_degenerate", 1.0, f"{text}: {what}", detail=what)]


def diagnose_api(functions):
    """other_api when some function was called through an adapter (another year's API):
    functions are submission.Found values, which carry the adapter and its one-line note."""
    notes = [f.api for f in functions.values() if getattr(f, "adapter", None)]
    notes = list(dict.fromkeys(notes))
    if not notes:
        return []
    return [Cause("other_api", 1.0, "; ".join(notes), detail="; ".join(notes))]


VERDICTS = ("timeout", "memory", "crashed", "forbidden")


def diagnose_verdicts(results, calls):
    """The sandbox's verdicts as causes (besides the tests' statuses): one per kind, its
    evidence the first call that ended so and how many did. results: {call id: CallResult};
    calls: the battery's calls, in order (for the function each called)."""
    causes = []
    for verdict in VERDICTS:
        hit = [c for c in calls if getattr(results.get(c["id"]), "status", "") == verdict]
        if not hit:
            continue
        first = results[hit[0]["id"]]
        detail = (first.detail.strip().splitlines() or [verdict])[0]
        more = f" (and {len(hit) - 1} more calls)" if len(hit) > 1 else ""
        causes.append(Cause(verdict, 1.0, f"call `{hit[0]['id']}` ({hit[0]['func']}): "
                            f"{first.detail.strip()[:600]}{more}", detail=detail))
    return causes
