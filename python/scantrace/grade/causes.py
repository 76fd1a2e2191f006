"""The causes: stable ids, the sentence a student reads, the fix, and the evidence that confirmed
each. A cause is reported only when a probe or an image model confirms it (confidence >= the
threshold below); what no model explains stays a plain pixel difference.
"""

import dataclasses
import json
import pathlib

# A cause is named when its model explains at least this fraction of the rows (probes) or
# pixels (images) where the submission differs from the reference.
CONFIDENCE = 0.9


def _load_catalogue():
    """The one mistake catalogue, mistakes.json beside this file: read here, embedded
    into the C++ `diff` at build time (grade/CMakeLists.txt) and named by the tests' wrong
    renderers. Returns (the document, {id: (sentence, fix)})."""
    path = pathlib.Path(__file__).resolve().with_name("mistakes.json")
    doc = json.loads(path.read_text(encoding="utf-8"))
    return doc, {m["id"]: (m["sentence"], m["fix"]) for m in doc["mistakes"]}


_DOCUMENT, CATALOGUE = _load_catalogue()
# diff's verdict sentence per id (where an image shows the mistake).
VERDICTS = {m["id"]: m["verdict"] for m in _DOCUMENT["mistakes"] if m.get("verdict")}
# The whole-image thresholds, the same numbers as diff's (grade/global_mistakes.cpp).
WHOLE_IMAGE = {k: v for k, v in _DOCUMENT["whole_image"].items() if k != "about"}


@dataclasses.dataclass
class Cause:
    id: str
    confidence: float
    evidence: str
    detail: str = ""
    picture: str | None = None          # file name of the evidence picture, beside the report
    picture_pixels: object = None       # the picture itself, written by the report
    legend: str = "grey: both; red: expected only; blue: yours only"   # what the picture shows
    test: str = ""      # the name of the test whose visible output shows it (set by the battery)

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
