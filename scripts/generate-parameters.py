#!/usr/bin/env python3
"""Writes Documentation/parameters.md from the public headers.

    python3 scripts/generate-parameters.py            # rewrite the file
    python3 scripts/generate-parameters.py --check    # diff, exit 1 if stale
    python3 scripts/generate-parameters.py --defaults-json  # defaults, JSON

The page is scripts/parameters.md.in with each directive line replaced by a
table built from a header:

    {{settings Rendering/DeepGBuffer/vtkDeepGBufferPass.h}}
    {{state Rendering/DeepGBuffer/vtkDeepGBufferPass.h}}

"settings" lists the header's settings (name, type, unit, range, default,
meaning), "state" its read-only state (name, type, unit, meaning), in the
order the header declares them. With " with bases" after the header
({{settings Reference/vtkDeepGIReferenceObscurance.h with bases}}) the table
goes on with the entries of the class's base classes in the sources, the
nearest base first: the class's whole set of parameters, for a class whose
bases have no section of their own.

The header form. A setting or a read-only value is a doc comment
(/** ... */ or a run of ///) followed by its declarations; the comment's
text is the meaning, and its last lines are tags:

    /**
     * Minimum separation dz between consecutive layers. Setting a value
     * switches AutomaticMinimumSeparation off.
     *
     * @unit world units
     * @range >= 0, finite; negative: warning, 0; NaN/inf: warning, ignored
     * @default 0 (unused while automatic)
     */
    void SetMinimumSeparation(double dz);
    vtkGetMacro(MinimumSeparation, double);

- @default marks a setting (required for one); its value is what the
  constructor sets. A plain number, on/off, an enum name, a quoted string,
  null or a tuple "(0, 0, 1)", optionally followed by a remark in
  parentheses, is checked against Get<Name>() by
  Testing/Documentation/CheckParameterDefaults.py; other values (words such
  as "automatic") are documented only.
- @readonly marks a read-only value of the last frame (no value).
- @unit, @range: optional; a tag's text may continue on the next lines.
- @type: optional; otherwise the type of the first VTK Set/Get macro or
  Set/Get method after the comment (bool, int, double[3], vtkRenderPass*,
  string, ...).
- @label: optional; the name column when it is not the declared name.

The name is that of the first Set/Get macro or method after the comment.
--check also fails for a setting declared with a VTK Set or Boolean macro
in a covered header that has no such comment, and for a hand-written row of
the template (| `Name...` | meaning |: the constants, helpers and methods
under each "## vtkClass") whose name is declared neither in vtkClass.h nor
in the headers of its base classes (a `Other::Name` row: in Other.h), or
whose meaning starts with a number that is not the constant's value there.
For Doxygen, define the tags as paragraphs in the Doxyfile:
ALIASES = "unit=@par Unit:^^" "range=@par Range:^^" "default=@par Default:^^"
          "type=@par Type:^^" "readonly=" "label=@par Name:^^"
"""
import argparse
import difflib
import json
import os
import re
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEMPLATE = os.path.join(REPO, "scripts", "parameters.md.in")
OUTPUT = os.path.join(REPO, "Documentation", "parameters.md")

TAGS = ("unit", "range", "default", "type", "readonly", "label")
TAG_LINE = re.compile(r"^@(%s)\b\s*(.*)$" % "|".join(TAGS))
DIRECTIVE = re.compile(r"^\{\{(settings|state) (\S+\.h)( with bases)?\}\}$")
CLASS = re.compile(r"^class\s+(?:\w+_EXPORT\s+)?(\w+)\s*(?::|$)", re.M)
COMMENT = re.compile(r"/\*\*(.*?)\*/|((?:^[ \t]*///(?!@)[^\n]*\n)+)", re.S | re.M)

# The declaration that names an entry and gives its type.
MACRO = re.compile(r"\bvtk(?:DeepGI)?(?:Set|Get|Boolean)(\w*)Macro\(\s*(\w+)\s*(?:,\s*([^,)]+))?")
METHOD = re.compile(
    r"^\s*(?:virtual\s+|static\s+)?([\w:]+(?:\s*\*)?)\s+(Set|Get)(\w+)\s*\(([^)]*)\)", re.M)


def comment_lines(match):
    """The text lines of a doc comment, without the comment markers."""
    if match.group(1) is not None:
        lines = match.group(1).split("\n")
        return [re.sub(r"^\s*\*?\s?", "", line).rstrip() for line in lines]
    return [re.sub(r"^\s*///\s?", "", line).rstrip() for line in match.group(2).split("\n")]


def split_tags(lines):
    """The meaning (joined prose) and the tags of a comment's lines."""
    prose, tags, current = [], {}, None
    for line in lines:
        tag = TAG_LINE.match(line.strip())
        if tag:
            current = tag.group(1)
            tags[current] = tag.group(2).strip()
        elif current is not None and line.strip():
            tags[current] = (tags[current] + " " + line.strip()).strip()
        elif current is None and line.strip() not in ("@{", "@}"):
            prose.append(line.strip())
    return " ".join(" ".join(prose).split()), tags


def macro_type(suffix, argument):
    """The documented type of a VTK Set/Get macro's value."""
    if "String" in suffix:
        return "string"
    if suffix.startswith("Object"):
        return argument + "*"
    vector = re.match(r"Vector(\d)", suffix)
    if vector:
        return "%s[%s]" % (argument, vector.group(1))
    return argument


def declaration(text):
    """(name, type) of the first Set/Get macro or method in `text`."""
    macro = MACRO.search(text)
    method = METHOD.search(text)
    if macro and (not method or macro.start() < method.start()):
        suffix, name, argument = macro.groups()
        return name, macro_type(suffix, (argument or "bool").strip())
    if method:
        returned, kind, name, arguments = method.groups()
        if kind == "Set":
            argument = arguments.split(",")[0].strip()
            returned = re.sub(r"\s*\b\w+$", "", argument) if " " in argument else argument
        returned = returned.replace("const char*", "string").replace(" *", "*")
        return name, returned
    return None, None


def entries(header):
    """The documented settings and read-only values of a header, in order."""
    with open(os.path.join(REPO, header)) as f:
        text = f.read()
    found = []
    for match in COMMENT.finditer(text):
        meaning, tags = split_tags(comment_lines(match))
        if "default" not in tags and "readonly" not in tags:
            continue
        name, kind = declaration(text[match.end():])
        if name is None:
            sys.exit("%s: no declaration after the comment at offset %d" % (header, match.start()))
        found.append({
            "name": tags.get("label") or name,
            "getter": name,
            "type": tags.get("type") or kind,
            "unit": tags.get("unit", ""),
            "range": tags.get("range", ""),
            "default": tags.get("default"),
            "meaning": meaning,
            "setting": "default" in tags,
        })
    return found


def base_headers(header):
    """The headers (repository-relative) of the base classes of the class of
    `header` that are in the sources, the nearest first."""
    found = []
    name = class_name(header)
    while True:
        with open(os.path.join(REPO, header)) as f:
            base = re.search(r"class\s+\w+\s+%s\s*:\s*public\s+(\w+)" % name, f.read())
        header = base and class_header(base.group(1))
        if not header:
            return found
        header = os.path.relpath(header, REPO)
        name = base.group(1)
        found.append(header)


def covered(header, with_bases):
    """The headers a directive's table is built from."""
    return [header] + (base_headers(header) if with_bases else [])


def class_name(header):
    with open(os.path.join(REPO, header)) as f:
        match = CLASS.search(f.read())
    if not match:
        sys.exit("%s: no class" % header)
    return match.group(1)


def cell(text):
    return text.replace("|", "\\|")


def code(name):
    return name if name.startswith("`") else "`%s`" % name


def settings_table(headers):
    rows = ["| name | type | unit | range | default | meaning |",
            "|------|------|------|-------|---------|---------|"]
    for e in [e for header in headers for e in entries(header)]:
        if e["setting"]:
            rows.append("| %s | %s | %s | %s | %s | %s |" % tuple(cell(x) for x in (
                code(e["name"]), e["type"], e["unit"], e["range"], e["default"], e["meaning"])))
    return rows


def state_table(headers):
    rows = ["| name | type | unit | meaning |", "|------|------|------|---------|"]
    for e in [e for header in headers for e in entries(header)]:
        if not e["setting"]:
            rows.append("| %s | %s | %s | %s |" % tuple(cell(x) for x in (
                code(e["name"]), e["type"], e["unit"], e["meaning"])))
    return rows


def directives():
    """(kind, headers) of each directive of the template, in order: the
    directive's header, then those of its bases when it names them."""
    with open(TEMPLATE) as f:
        for line in f:
            match = DIRECTIVE.match(line.strip())
            if match:
                yield match.group(1), covered(match.group(2), match.group(3))


def generate():
    out = []
    with open(TEMPLATE) as f:
        for line in f.read().split("\n"):
            match = DIRECTIVE.match(line.strip())
            if not match:
                out.append(line)
            elif match.group(1) == "settings":
                out.extend(settings_table(covered(match.group(2), match.group(3))))
            else:
                out.extend(state_table(covered(match.group(2), match.group(3))))
    return "\n".join(out)


def defaults():
    """{class: {getter name: documented default}} of every covered setting."""
    result = {}
    for kind, headers in directives():
        if kind == "settings":
            values = result.setdefault(class_name(headers[0]), {})
            for e in [e for header in headers for e in entries(header)]:
                if e["setting"]:
                    values[e["getter"]] = e["default"]
    return result


# A setting declared with a VTK Set or Boolean macro.
SETTING_MACRO = re.compile(r"\bvtk(?:DeepGI)?(?:Set\w*|Boolean)Macro\(\s*(\w+)")


def undocumented():
    """(header, name) of each macro-declared setting of a covered header
    that has no tagged comment."""
    missing = []
    for kind, header in sorted({(k, h) for k, headers in directives() for h in headers}):
        if kind == "settings":
            with open(os.path.join(REPO, header)) as f:
                declared = set(SETTING_MACRO.findall(f.read()))
            documented = {e["getter"] for e in entries(header)}
            missing += [(header, name) for name in sorted(declared - documented)]
    return missing


def class_header(name):
    """The public header of class `name`: the file name.h in the sources."""
    for folder, dirs, files in os.walk(REPO):
        dirs[:] = [d for d in dirs if not d.startswith(".") and not d.startswith("build")]
        if name + ".h" in files:
            return os.path.join(folder, name + ".h")
    return None


def class_text(name):
    """The header of class `name` and those of its base classes in the
    sources (inherited constants and methods are documented with the
    class)."""
    header = class_header(name)
    if not header:
        return ""
    with open(header) as f:
        text = f.read()
    base = re.search(r"class\s+\w+\s+%s\s*:\s*public\s+(\w+)" % name, text)
    return text + (class_text(base.group(1)) if base else "")


def declared(name, source):
    """Whether `name` is declared in `source`, directly or as the getter or
    setter a VTK Get/Set macro makes."""
    if re.search(r"\b%s\b" % name, source):
        return True
    accessor = re.match(r"(?:Get|Set)(\w+)", name)
    return bool(accessor and re.search(r"Macro\(\s*%s\b" % accessor.group(1), source))


# A hand-written row of the template: | `Name...` | meaning |
HAND_ROW = re.compile(r"^\| `(?:\w+::)?(\w+)[^|]*\| ([^|]*)\|")
# A meaning that starts with a number: the constant's value.
LEADING_NUMBER = re.compile(r"^([0-9]+(?:\.[0-9]+)?)\b")


def stale_hand_rows():
    """The template's hand-written rows (constants, helpers, methods) whose
    name is not declared in their class's header, or whose leading number
    is not the constant's value there."""
    problems = []
    text = ""
    header = None
    with open(TEMPLATE) as f:
        for number, line in enumerate(f, 1):
            if line.startswith("## "):
                header = class_header(line[3:].strip())
                text = class_text(line[3:].strip())
                if not header:
                    problems.append("%d: no header for %s" % (number, line[3:].strip()))
                continue
            match = HAND_ROW.match(line)
            if not match or not header:
                continue
            name, meaning = match.group(1), match.group(2).strip()
            where = "scripts/parameters.md.in:%d: %s" % (number, name)
            qualified = re.match(r"\| `(\w+)::", line)
            source = text
            if qualified and qualified.group(1) + ".h" != os.path.basename(header):
                source = class_text(qualified.group(1))
            if not declared(name, source):
                problems.append(where + " is not declared in its header")
                continue
            value = LEADING_NUMBER.match(meaning)
            constant = re.search(r"\b%s\s*=\s*([0-9.]+)" % name, source)
            if value and constant and float(value.group(1)) != float(constant.group(1).rstrip(".")):
                problems.append("%s is %s in its header, %s in the template"
                                % (where, constant.group(1), value.group(1)))
    return problems


def check(generated):
    missing = undocumented()
    for header, name in missing:
        print("%s: the setting %s has no comment with @default" % (header, name))
    stale = stale_hand_rows()
    for problem in stale:
        print(problem)
    missing += stale
    with open(OUTPUT) as f:
        current = f.read()
    if current == generated and not missing:
        return 0
    if current == generated:
        return 1
    sys.stdout.writelines(difflib.unified_diff(
        current.splitlines(True), generated.splitlines(True),
        "Documentation/parameters.md", "generated from the headers"))
    print("\nDocumentation/parameters.md is not what the headers give; "
          "run python3 scripts/generate-parameters.py")
    return 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="exit 1 with a unified diff when the file differs")
    parser.add_argument("--defaults-json", action="store_true",
                        help="print the documented defaults of every class as JSON")
    args = parser.parse_args()
    if args.defaults_json:
        json.dump(defaults(), sys.stdout, indent=1, ensure_ascii=False)
        print()
        return 0
    generated = generate()
    if args.check:
        return check(generated)
    with open(OUTPUT, "w") as f:
        f.write(generated)
    return 0


if __name__ == "__main__":
    sys.exit(main())
