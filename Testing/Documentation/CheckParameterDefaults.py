"""The defaults Documentation/parameters.md states are the real ones.

    python3 CheckParameterDefaults.py <scripts/generate-parameters.py>

Runs the generator with --defaults-json (the @default tags of the headers),
creates each documented class with New() and compares Get<Name>() with
every default that is a plain value: a number, on/off, an enum name of the
class, a quoted string, null, empty or a tuple "(0, 0, 1)", optionally
followed by a remark in parentheses. Other defaults (a description such as
"a vtkTranslucentPass") and settings without a getter are skipped and
listed; classes this build does not have (optional modules) are skipped
and listed too. Exits 1 when a default differs.
"""
import json
import math
import re
import subprocess
import sys

import vtkdeepgi

NUMBER = r"[-+]?(?:inf|(?:\d[\d,]*\.?\d*|\.\d+)(?:e[-+]?\d+)?)"
TUPLE = re.compile(r"^\((%s(?:,\s*%s)+)\)$" % (NUMBER, NUMBER))
REMARK = re.compile(r"\s+\(.*\)$")
WORDS = {"on": True, "off": False, "null": None, "empty": None}


class NotPlain(Exception):
    """A default that describes the value instead of stating it."""


def number(text):
    text = text.replace(",", "")
    value = float(text)
    return int(value) if re.match(r"^[-+]?\d+$", text) else value


def expected_value(cls, text):
    """The value `text` documents, or NotPlain."""
    text = REMARK.sub("", text.replace("\u2212", "-").strip())
    match = TUPLE.match(text)
    if match:
        return tuple(number(x.strip()) for x in match.group(1).split(","))
    if text in WORDS:
        return WORDS[text]
    if re.match(r"^%s$" % NUMBER, text):
        return number(text)
    if re.match(r'^"[^"]*"$', text):
        return text[1:-1]
    if re.match(r"^[A-Z][A-Z0-9_]+$", text) and hasattr(cls, text):
        return int(getattr(cls, text))
    raise NotPlain(text)


def same(actual, expected):
    if expected is None:
        return actual in (None, "")
    if isinstance(expected, tuple):
        return (isinstance(actual, tuple) and len(actual) == len(expected)
                and all(same(a, e) for a, e in zip(actual, expected)))
    if isinstance(expected, bool) or isinstance(actual, bool):
        return bool(actual) == expected
    if isinstance(expected, str):
        return actual == expected
    if math.isinf(expected):
        return actual == expected
    return math.isclose(actual, expected, rel_tol=1e-9, abs_tol=1e-12)


def check_class(name, settings, failures, skipped):
    cls = getattr(vtkdeepgi, name, None)
    if cls is None:
        skipped.append("%s: class not built" % name)
        return 0
    try:
        obj = cls()
    except TypeError:
        skipped.append("%s: abstract class" % name)
        return 0
    checked = 0
    for setting, text in settings.items():
        getter = getattr(obj, "Get" + setting, None)
        try:
            expected = expected_value(cls, text)
        except NotPlain:
            skipped.append("%s.%s: default %r is not a plain value" % (name, setting, text))
            continue
        if getter is None:
            skipped.append("%s.%s: no Get%s()" % (name, setting, setting))
            continue
        actual = getter()
        checked += 1
        if not same(actual, expected):
            failures.append("%s.Get%s() is %r; documented default %r (%s)"
                            % (name, setting, actual, text, expected))
    return checked


def main():
    generator = sys.argv[1]
    documented = json.loads(subprocess.check_output(
        [sys.executable, generator, "--defaults-json"], text=True))
    failures, skipped = [], []
    checked = sum(check_class(name, settings, failures, skipped)
                  for name, settings in documented.items())
    for line in skipped:
        print("skipped " + line)
    for line in failures:
        print("FAIL " + line)
    print("%d documented defaults checked, %d skipped, %d wrong"
          % (checked, len(skipped), len(failures)))
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
