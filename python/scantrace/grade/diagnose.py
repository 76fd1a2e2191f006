"""From the student's results to causes: each candidate mistake is a model (fill_models.py for the
fill, a permutation or a re-ordered render for colours and order); a cause is the model that
explains what the submission did where the correct model does not.
"""

import itertools
import math

import numpy as np

from . import fill_models
from .causes import CONFIDENCE, WHOLE_IMAGE, Cause  # noqa: F401 - Cause is used by battery too

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


def diagnose_fill(results):
    """results: [(probe, student mask)] from f_shading on blank canvases. Returns causes."""
    plain = [(p, m) for p, m in results if not fill_models.degenerate(p.array)]
    correct = {p.name: fill_models.correct(p.array, p.size) for p, _ in results}
    wrong = {(p.name, r) for p, m in plain for r in _rows_differing(m, correct[p.name])}
    causes = []
    if wrong:
        scores = []
        for key, model in fill_models.MODELS.items():
            masks = {p.name: model(p.array, p.size) for p, _ in plain}
            bad = {(p.name, r) for p, m in plain for r in _rows_differing(m, masks[p.name])}
            scores.append((len(bad), key, masks))
        scores.sort(key=lambda s: s[0])
        best_bad = scores[0][0]
        for bad, (cause_id, variant), masks in scores:
            confidence = 1 - bad / len(wrong)
            if key_is_drift(cause_id) and bad > 0:
                # Drift depends on how the student accumulated: accept the signature.
                if all(_drift_signature(p, m, correct[p.name]) for p, m in plain):
                    confidence = max(confidence, CONFIDENCE)
            if confidence < CONFIDENCE or bad > best_bad and not key_is_drift(cause_id):
                continue
            candidates = [(p, m) for p, m in plain if _rows_differing(m, correct[p.name])]
            exact = [(p, m) for p, m in candidates if (m == masks[p.name]).all()]
            probe, mask = (exact or candidates)[0]
            text, _ = _fill_evidence(probe, mask, masks[probe.name], correct[probe.name])
            if not any(c.id == cause_id for c in causes):
                causes.append(Cause(cause_id, confidence, text, detail=variant or "",
                                    picture_pixels=fill_picture(mask, correct[probe.name])))
    drawn = [(p, m) for p, m in results if fill_models.degenerate(p.array) and m.any()]
    if drawn:
        p, m = drawn[0]
        causes.append(Cause("degenerate_drawn", 1.0,
                            f"probe `{p.name}` ({p.what}: "
                            + " ".join(f"({x:g}, {y:g})" for x, y in p.vertices)
                            + f"), row {min(fill_models.row_spans(m))}: expected columns "
                            f"nothing, yours {_fmt_span(fill_models.row_spans(m), min(fill_models.row_spans(m)))}"
                            f" ({int(m.sum())} pixels in all)",
                            picture_pixels=fill_picture(m, correct[p.name])))
    return causes


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
    d = np.abs(a - b)
    return np.maximum(np.maximum(d[..., 0], d[..., 1]), d[..., 2])


def image_mismatch(a, b):
    """The fraction of pixels whose colour differs by more than 1.5/255 in some channel."""
    return float((channel_error(a, b) > 1.5 / 255).mean())


def diagnose_image(student, reference, uncovered, alternatives):
    """Global mistakes of a rendered image, undone in order so the rest can be graded: a
    transpose, BGR channels, a background colour; then the painter's order, from
    `alternatives` {cause id: the reference rendered with that mistake}. Returns (image, causes)."""
    causes = []
    base = image_mismatch(student, reference)
    for cause_id, fix in (("transposed", lambda s: s.transpose(1, 0, 2)),
                          ("bgr", lambda s: s[..., ::-1])):
        if base == 0 or student.shape[0] != student.shape[1] and cause_id == "transposed":
            continue
        fixed = np.ascontiguousarray(fix(student))
        m = image_mismatch(fixed, reference)
        if m < base / WHOLE_IMAGE["transform_gain"]:  # the catalogue's, as diff's
            differ = channel_error(student, reference) > 1.5 / 255
            causes.append(Cause(cause_id, 1 - m / base,
                                f"{base:.1%} of the pixels differ; {m:.1%} after undoing it",
                                picture_pixels=image_picture(student, reference, differ),
                                legend=IMAGE_LEGEND))
            student, base = fixed, m
    if uncovered.any() and base > 0:
        bg = np.median(student[uncovered], axis=0)
        if np.abs(bg - 1.0).max() > 2 / 255:
            same = uncovered & (channel_error(student, bg) <= 1.5 / 255)
            share = same.sum() / uncovered.sum()
            if share >= WHOLE_IMAGE["background_share"]:
                picture = image_picture(student, reference, same)
                student = student.copy()
                student[same] = 1.0
                causes.append(Cause("background", share,
                                    f"{share:.0%} of the pixels no face covers are "
                                    f"{_describe_colour(bg)}", detail=_describe_colour(bg),
                                    picture_pixels=picture, legend=IMAGE_LEGEND))
                base = image_mismatch(student, reference)
    for cause_id, alt in alternatives.items():
        # Only the pixels this order changes decide (a wrong fill elsewhere does not blur it).
        deciding = channel_error(alt, reference) > 1.5 / 255
        if base == 0 or not deciding.any():
            continue
        close = 1.5 / 255
        as_alt = int((channel_error(student, alt)[deciding] <= close).sum())
        as_ref = int((channel_error(student, reference)[deciding] <= close).sum())
        if as_alt >= 0.5 * deciding.sum() and as_alt > 2 * as_ref:
            causes.append(Cause(cause_id, as_alt / (as_alt + as_ref),
                                f"of the {int(deciding.sum())} pixels this order changes, yours "
                                f"has {as_alt} as painted in this order and {as_ref} as in the "
                                "correct one",
                                picture_pixels=image_picture(student, reference, deciding),
                                legend=IMAGE_LEGEND))
    return student, causes


def diagnose_vector_interp(failures):
    """failures: [(case text, what happened)] of the degenerate vector_interp cases."""
    if not failures:
        return []
    text, what = failures[0]
    return [Cause("vector_interp_degenerate", 1.0, f"{text}: {what}", detail=what)]
