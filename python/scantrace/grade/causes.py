"""The causes: stable ids, the sentence a student reads, the fix, and the evidence that confirmed
each. A cause is reported only when a probe or an image model confirms it (confidence >= the
threshold below); what no model explains stays a plain pixel difference.
"""

import dataclasses

# A cause is named when its model explains at least this fraction of the rows (probes) or
# pixels (images) where the submission differs from the reference.
CONFIDENCE = 0.9

CATALOGUE = {
    "span_end_rounding": (
        "Span ends are {detail} instead of ceil(): on rows where an edge crosses between pixel "
        "centres the span starts or ends one pixel off.",
        "fill columns ceil(x_L) … ceil(x_R) − 1: `range(math.ceil(xl), math.ceil(xr))`"),
    "right_end_excluded": (
        "The last pixel of a span is left out when the right edge crosses the row between pixel "
        "centres (the loop stops at floor(x_R)).",
        "end the span at ceil(x_R), exclusive: `range(math.ceil(xl), math.ceil(xr))`"),
    "closed_rule": (
        "Pixels whose centre lies exactly on a right or bottom edge are filled too (a closed "
        "rule), so two faces sharing an edge both write it.",
        "use the half-open rule: rows ceil(y_min) … ceil(y_max) − 1, columns ceil(x_L) … "
        "ceil(x_R) − 1"),
    "span_too_wide": (
        "Spans run from floor(x_L) to ceil(x_R) inclusive — the pixels a line drawing of the "
        "edges lights — one pixel too wide at both ends.",
        "fill only the pixels whose centre is inside: columns ceil(x_L) … ceil(x_R) − 1"),
    "top_row_dropped": (
        "The first row of each triangle (y = ceil(y_min)) is not filled.",
        "start the row loop at ceil(y_min): `range(math.ceil(ymin), math.ceil(ymax))`"),
    "bottom_row_dropped": (
        "The last row of each triangle (y = ceil(y_max) − 1) is not filled.",
        "end the row loop at ceil(y_max), exclusive: `range(math.ceil(ymin), math.ceil(ymax))`"),
    "edge_lag": (
        "Each edge's x is updated after its row is drawn, so every row uses the previous row's "
        "crossing: the face is shifted sideways by one row's slope.",
        "compute the crossing for row y before filling it: x = x_top + (y − y_top)·dx/dy"),
    "float_drift": (
        "x is accumulated as x += dx/dy in floating point; on rows where the edge crosses a "
        "pixel centre exactly, the sum is a hair off and ceil() moves the span end by one pixel.",
        "compute x from the edge's start on every row: x0 + (y − y0)·(x1 − x0)/(y1 − y0)"),
    "horizontal_edge_skipped": (
        "Triangles with a horizontal edge are not drawn at all (a guard against dy = 0 in the "
        "slope returns from the whole face), though a horizontal edge only means the edge is "
        "never active.",
        "skip only the horizontal edge, not the face: leave it out of the edge list (`if a[1] == "
        "b[1]: continue`) and fill the rows with the other two"),
    "canvas_border_clipped": (
        "The canvas's {detail} are never written: the bounds check around `img[y, x] = …` is "
        "off by one, so a face reaching that border loses its pixels there.",
        "write every pixel with 0 ≤ x < W and 0 ≤ y < H: `if 0 <= x < img.shape[1] and 0 <= y "
        "< img.shape[0]`"),
    "degenerate_drawn": (
        "Zero-area (collinear) faces are drawn; no pixel centre is inside them, so they must "
        "fill nothing.",
        "skip a face whose doubled area (x1−x0)(y2−y0) − (x2−x0)(y1−y0) is 0"),
    "flat_colour_not_mean": (
        "Flat shading fills with {detail} instead of the mean of the three vertex colours.",
        "fill with `np.mean(vcolors, axis=0)`"),
    "gouraud_weights_permuted": (
        "Gouraud colours are attached to the wrong vertices: {detail}.",
        "interpolate each vertex's own colour: vcolors[i] belongs to vertices[i]"),
    "colours_paired_after_sort": (
        "The vertices are sorted by y but their colours are not, so after the sort the colours "
        "no longer follow their vertices.",
        "sort both with one index: `order = np.argsort(vertices[:, 1]); vertices, vcolors = "
        "vertices[order], vcolors[order]`"),
    "transposed": (
        "The image is indexed img[x][y] (transposed); pixel (x, y) is img[y][x].",
        "write `img[y, x] = colour` (row first); the grader undid the transpose to grade the rest"),
    "bgr": (
        "The colour channels are in BGR order; the course's images are RGB.",
        "keep the channels as given (OpenCV's BGR is only for cv2.imwrite); the grader swapped "
        "them back to grade the rest"),
    "background": (
        "The background is {detail} instead of white (1, 1, 1).",
        "start render_img from `np.ones((512, 512, 3))`"),
    "scaled_255": (
        "The image holds colours on a 0–255 scale; the course's images are floats in [0, 1].",
        "write colours in [0, 1] (the vcolors as given, on `np.ones((512, 512, 3))`): divide by "
        "255 only when saving 8-bit files; the grader rescaled yours to grade the rest"),
    "order_reversed": (
        "Faces are painted nearest first; the painter's algorithm draws the deepest face (the "
        "largest mean depth) first.",
        "sort by mean depth, largest first: `np.argsort(-depth, kind='stable')`"),
    "order_unstable_on_ties": (
        "Faces of equal mean depth are not painted in face order (an unstable sort, or a "
        "reversed argsort), so ties are drawn the wrong way round.",
        "use a stable sort on the negated depth: `np.argsort(-depth, kind='stable')`"),
    "other_api": (
        "Your functions follow another year's API ({detail}); the course's are "
        "vector_interp(p1, p2, V1, V2, coord, dim), f_shading(img, vertices, vcolors), "
        "g_shading(img, vertices, vcolors) and render_img(faces, vertices, vcolors, depth, "
        "shading) with shading 'f' or 'g'. The grader called yours through an adapter.",
        "use the course's names, parameters and shading values, so that the course's own code "
        "can call your functions"),
    "timeout": (
        "Your code ran past its time limit ({detail}).",
        "look for a loop that never ends (a while whose variable is never updated) or work done "
        "for every pixel of the canvas on every face; a 512 x 512 scene of 10,000 faces must "
        "take seconds, not minutes"),
    "memory": (
        "Your code ran out of memory ({detail}).",
        "do not allocate arrays per pixel or per face that grow with the scene (a 512 x 512 x 3 "
        "canvas is 6 MB): reuse the canvas you are given"),
    "crashed": (
        "The Python interpreter running your code stopped in the middle ({detail}).",
        "do not call sys.exit(), os._exit() or native code; let an error be raised instead, "
        "and keep demos under `if __name__ == \"__main__\":`"),
    "forbidden": (
        "Your code tried something the grader does not allow ({detail}).",
        "use only the arguments you are given: no files outside your submission (load hw1.npy "
        "only in your demo, under `if __name__ == \"__main__\":`), no network, no other "
        "programs, no megabytes of printing"),
    "vector_interp_degenerate": (
        "vector_interp fails when p1 and p2 have the same coordinate along dim: {detail}.",
        "when the two coordinates are equal, return V1 (or the midpoint) instead of dividing "
        "by zero"),
}


@dataclasses.dataclass
class Cause:
    id: str
    confidence: float
    evidence: str
    detail: str = ""
    picture: str | None = None          # file name of the evidence picture, beside the report
    picture_pixels: object = None       # the picture itself, written by the report
    legend: str = "grey: both; red: expected only; blue: yours only"   # what the picture shows

    @property
    def sentence(self):
        return CATALOGUE[self.id][0].format(detail=self.detail)

    @property
    def fix(self):
        return CATALOGUE[self.id][1]

    def as_json(self):
        return {"id": self.id, "sentence": self.sentence, "fix": self.fix,
                "evidence": self.evidence, "confidence": round(self.confidence, 3),
                **({"picture": self.picture} if self.picture else {})}
