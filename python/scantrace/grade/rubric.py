"""The rubric: the total, each test's weight and visibility, the points a cause takes off, from a
TOML file (default_rubric.toml unless --rubric names another; keys it leaves out keep their
default). Any key or section the default does not know is a usage error (RubricError: exit 2)."""

import dataclasses
import pathlib
import tomllib

from .causes import CATALOGUE

DEFAULT = pathlib.Path(__file__).with_name("default_rubric.toml")

# Gradescope's values of a test's `visibility`.
VISIBILITIES = ("visible", "hidden", "after_due_date", "after_published")


class RubricError(ValueError):
    pass


@dataclasses.dataclass
class Rubric:
    tests: dict            # rubric key: weight (relative; the points are shared out of `total`)
    causes: dict           # cause id: points taken off
    hidden_scenes: int
    total: float = 100.0
    visibilities: dict = dataclasses.field(default_factory=dict)

    def points(self, key):
        """The weight of a test (scoring.allot turns the weights into points of `total`)."""
        return float(self.tests[key])

    def runs(self, key):
        """A test weighted 0 is not run."""
        return self.points(key) > 0

    def visibility(self, key):
        return self.visibilities.get(key, "visible")

    def deduction(self, cause_id):
        return float(self.causes.get(cause_id, 0))


def _number(path, section, key, value):
    if not isinstance(value, (int, float)) or isinstance(value, bool) or value < 0:
        raise RubricError(f"{path}: [{section}] {key}: expected a number >= 0, got {value!r}")


def _check(path, section, values, data):
    """One section of the user's rubric against the default's keys and the value types."""
    known = {"tests": data["tests"], "causes": CATALOGUE, "visibility": data["tests"],
             "hidden": data["hidden"], "score": data["score"]}[section]
    for key, value in values.items():
        if key not in known:
            raise RubricError(f"{path}: [{section}] {key}: no such key (known: "
                              + ", ".join(sorted(known)) + ")")
        if section == "visibility":
            if value not in VISIBILITIES:
                raise RubricError(f"{path}: [visibility] {key}: expected one of "
                                  + ", ".join(VISIBILITIES) + f", got {value!r}")
        elif section == "hidden" and (not isinstance(value, int) or isinstance(value, bool)
                                      or not 0 <= value <= 20):
            raise RubricError(f"{path}: [hidden] {key}: expected a whole number 0…20, "
                              f"got {value!r}")
        else:
            _number(path, section, key, value)


def load(path=None):
    with open(DEFAULT, "rb") as f:
        data = tomllib.load(f)
    if path is not None:
        try:
            with open(path, "rb") as f:
                user = tomllib.load(f)
        except OSError as e:
            raise RubricError(f"{path}: cannot read the rubric: {e.strerror}") from None
        except tomllib.TOMLDecodeError as e:
            raise RubricError(f"{path}: not TOML: {e}") from None
        for section, values in user.items():
            if section not in data or not isinstance(values, dict):
                raise RubricError(f"{path}: unknown section [{section}] (expected "
                                  + ", ".join(f"[{s}]" for s in data) + ")")
            _check(path, section, values, data)
            data[section].update(values)
    if data["score"]["total"] <= 0 or not any(v > 0 for v in data["tests"].values()):
        raise RubricError(f"{path or DEFAULT}: the total and at least one test's weight must "
                          "be > 0")
    return Rubric(data["tests"], data["causes"], int(data["hidden"]["scenes"]),
                  float(data["score"]["total"]), dict(data["visibility"]))
