"""The rubric: points per test and per cause, from a TOML file (default_rubric.toml unless
--rubric names another; keys it leaves out keep their default)."""

import dataclasses
import pathlib
import tomllib

DEFAULT = pathlib.Path(__file__).with_name("default_rubric.toml")


class RubricError(ValueError):
    pass


@dataclasses.dataclass
class Rubric:
    tests: dict
    causes: dict
    hidden_scenes: int

    def points(self, key):
        return float(self.tests[key])

    def deduction(self, cause_id):
        return float(self.causes.get(cause_id, 0))


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
                raise RubricError(f"{path}: unknown section [{section}] (expected [tests], "
                                  "[causes] or [hidden])")
            for key, value in values.items():
                if section == "tests" and key not in data["tests"]:
                    raise RubricError(f"{path}: [tests] {key}: no such test (known: "
                                      + ", ".join(data["tests"]) + ")")
                if not isinstance(value, (int, float)) or isinstance(value, bool) or value < 0:
                    raise RubricError(f"{path}: [{section}] {key}: expected a number >= 0, "
                                      f"got {value!r}")
            data[section].update(values)
    return Rubric(data["tests"], data["causes"], int(data["hidden"]["scenes"]))
