#!/usr/bin/python3
"""Makes a model's C++ key declarations (case_keys.hpp) from its keys.toml (issue 31: a key is
declared once, as data): case_keys.hpp declares the Keys struct, case_keys.cpp defines keys() and
case_keys(). The build runs it (models/CMakeLists.txt); the formats are in
tools/keygen/README.md.

usage: generate_case_keys.py KEYS.toml OUT.hpp OUT.cpp     (a model's keys)
       generate_case_keys.py --core core/keys.toml OUT.cpp   (the core readers' key groups)
"""

import json
import re
import sys
import tomllib

CORE_GROUPS = {  # a model's `core = NAME` entry: the core function that declares that group
    "particle_discretisation": "particle_discretisation_case_keys",
    "wall": "wall_case_keys",
    "domain": "domain_case_keys",
    "particle_block": "particle_block_case_keys",
}
VALUE_TYPES = {"number": "double", "integer": "std::int64_t", "boolean": "bool",
               "string": "std::string"}
KEY_TYPES = {"number": "number", "integer": "integer", "boolean": "boolean", "string": "string",
             "numbers": "numbers", "tables": "tables", "choice": "string"}
INTERVAL = re.compile(r"([\[(])\s*(-?inf|[-+0-9.e]+)\s*,\s*(-?inf|[-+0-9.e]+)\s*([\])])")


class KeyFileError(Exception):
    pass


def cpp(text):
    """A C++ string literal of `text` (UTF-8 kept as is)."""
    return json.dumps(text, ensure_ascii=False)


def bound(text, value_type):
    """An interval end as C++: nullopt for an infinite one, a double literal for a number."""
    if text.endswith("inf"):
        return "std::nullopt"
    if value_type == "double" and not re.search(r"[.e]", text):
        return text + ".0"
    return text


def interval_message(low_closed, low, high, high_closed):
    if high == "inf" and low == "-inf":
        return "must be finite"
    if high == "inf":
        return f"must be {'>=' if low_closed else '>'} {low}"
    if low == "-inf":
        return f"must be {'<=' if high_closed else '<'} {high}"
    return f"must be in {'[' if low_closed else '('}{low}, {high}{']' if high_closed else ')'}"


def check_expression(key, value_type):
    """The KeyCheck of a key's `check` (with `message`, `zero_means`), or "" for none."""
    check = key.get("check")
    if check is None:
        return ""
    if value_type == "double" and check == "> 0" and "message" not in key:
        return "positive_or_why"
    if value_type == "double" and check == ">= 0" and "message" not in key:
        return f"non_negative({cpp(key.get('zero_means', ''))})"
    shorthand = {"> 0": "(0, inf)", ">= 0": "[0, inf)", "finite": "(-inf, inf)"}
    match = INTERVAL.fullmatch(shorthand.get(check, check))
    if not match:
        raise KeyFileError(f"{key['path']}: check {check!r} is not \"> 0\", \">= 0\", "
                           "\"finite\" or an interval such as \"[1, 20]\" or \"(0, inf)\"")
    opening, low, high, closing = match.groups()
    message = key.get("message") or interval_message(opening == "[", low, high, closing == "]")
    return (f"within<{value_type}>({bound(low, value_type)}, {str(opening == '[').lower()}, "
            f"{bound(high, value_type)}, {str(closing == ']').lower()}, {cpp(message)})")


def declaration(key, text_parameters=None, list_parameters=()):
    """{path, KeyType, unit, default, meaning[, values]}: a key read elsewhere, or one of a core
    group whose meaning and values may name the group's parameters (text_parameters not None)."""
    meaning = cpp(key["meaning"]) if text_parameters is None else \
        text_expression(key["meaning"], text_parameters)
    fields = [cpp(key["path"]), "KeyType::" + KEY_TYPES[key["type"]], cpp(key.get("unit", "-")),
              cpp(key["default"]), meaning]
    values = key.get("values")
    if isinstance(values, str):
        if not values.startswith("@") or values[1:] not in list_parameters:
            raise KeyFileError(f"{key['path']}: values {values!r} names no list parameter")
        fields.append(values[1:])
    elif values is not None:
        fields.append("{" + ", ".join(cpp(v) for v in values) + "}")
    return "{" + ", ".join(fields) + "}"


def member(key, index):
    """One member of the Keys struct."""
    if "core" in key:
        group = CORE_GROUPS.get(key["core"])
        if group is None:
            raise KeyFileError(f"core group {key['core']!r}: one of {', '.join(CORE_GROUPS)}")
        if "kinds" in key:
            arguments = "{" + ", ".join(cpp(k) for k in key["kinds"]) + "}"
        else:
            arguments = ", ".join(cpp(a) for a in key.get("args", []))
        return f"const int core_group_{index} = declare({group}({arguments}));"
    # A key read elsewhere may go without a name (its path is not needed here).
    name, kind = key.get("name", f"declared_{index}"), key["type"]
    if kind == "gravity":
        return f"const Key<double> {name} = KeySet::gravity({cpp(key.get('detail', ''))});"
    if kind == "gravity_reference_height":
        return f"const Key<double> {name} = KeySet::gravity_reference_height();"
    if kind == "splitting":
        return f"const Choice<Splitting> {name} = KeySet::splitting({cpp(key['default'])});"
    if kind == "position_scale":
        return f"const PositionScaleKey {name} = position_scale();"
    if kind == "scale":
        if "magnitude" in key:
            return (f"const ScaleKey {name} = scale({cpp(key['quantity'])}, "
                    f"{cpp(key['magnitude'])}, {key['bits']}, {cpp(key['meaning'])}, "
                    f"{cpp(key.get('note', ''))});")
        path = f"fixed_point.{key['quantity']}_exponent"
        decl = declaration({"path": path, "type": "integer", "default": key["default"],
                            "meaning": key["meaning"]})
        return f"const ScaleKey {name}{{declare({decl}), {key['bits']}}};"
    if key.get("declared_only") or kind in ("numbers", "tables"):
        return f"const std::string {name} = declare({declaration(key)});"
    if kind == "choice":
        enum = key["enum"]
        if enum == "bool":
            if len(key["values"]) != 2:
                raise KeyFileError(f"{key['path']}: a bool choice has two values (false, true)")
            mapped = ["false", "true"]
        else:
            mapped = [f"{enum}::{e}" for e in key.get("enumerators", key["values"])]
        pairs = ", ".join(f"{{{cpp(v)}, {m}}}" for v, m in zip(key["values"], mapped))
        default = key["default"] if key["default"] == "required" else f'"{key["default"]}"'
        return (f"const Choice<{enum}> {name} = choice<{enum}>({cpp(key['path'])}, {cpp(default)}, "
                f"{cpp(key['meaning'])}, {{{pairs}}});")
    value_type = VALUE_TYPES.get(kind)
    if value_type is None:
        raise KeyFileError(f"{key.get('path', name)}: type {kind!r} unknown")
    arguments = [cpp(key["path"])]
    if kind == "number":
        arguments.append(cpp(key["unit"]))
    arguments += [cpp(key["default"]), cpp(key["meaning"])]
    check = check_expression(key, value_type)
    if check:
        if kind == "boolean":
            raise KeyFileError(f"{key['path']}: a boolean takes no check")
        arguments.append(check)
    function = {"number": "number", "integer": "integer", "boolean": "boolean",
                "string": "text"}[kind]
    return f"const Key<{value_type}> {name} = {function}({', '.join(arguments)});"


def is_literal(default, kind):
    """Whether a default's text is a value (read() can use it) rather than a description."""
    if kind == "number":
        try:
            float(default)
            return True
        except ValueError:
            return False
    if kind == "integer":
        return re.fullmatch(r"-?[0-9]+", default) is not None
    if kind == "boolean":
        return default in ("true", "false")
    return kind == "string" and len(default) >= 2 and default[0] == default[-1] == '"'


def field_reader(keys):
    """read_fields: every key with a `field` read into that member of the parameters."""
    lines = []
    for key in keys:
        if "field" in key:
            if key["type"] in VALUE_TYPES and key["default"] != "required" and \
                    not is_literal(key["default"], key["type"]):
                raise KeyFileError(f"{key['path']}: a field needs a literal default or "
                                   "\"required\" (this one is computed: read it by hand)")
            field = key["name"] if key["field"] is True else key["field"]
            lines.append(f"    p.{field} = {key['name']}.read(case_file);")
    if not lines:
        return []
    return ["  // A P whose members named by a key's `field` are read from the case file.",
            "  template <class P>", "  P read_fields(const CaseFile& case_file) const {", "    P p;",
            *lines, "    return p;", "  }"]


def generate(data):
    model = data["model"]
    keys = data["key"]
    body = []
    for index, key in enumerate(keys):
        try:
            body.append("  " + member(key, index))
        except KeyError as missing:
            raise KeyFileError(f"key {index} ({key.get('path', key.get('name', '?'))}): "
                               f"{missing} missing") from None
    return "\n".join([
        f"// Generated by tools/keygen/generate_case_keys.py from models/{model}/keys.toml: edit "
        "that file.",
        "#pragma once", "",
        '#include "core/case_key.hpp"',
        '#include "core/case_keys.hpp"',
        '#include "core/particle_discretisation.hpp"',
        '#include "core/step_splitting.hpp"',
        f'#include "models/{model}/parameters.hpp" // the enums the choices map to', "",
        "#include <cstdint>", "#include <optional>", "#include <string>", "",
        f"namespace revsph::{model} {{", "",
        "struct Keys : KeySet {",
        f"  Keys() : KeySet({cpp(model)}) {{}}",
        *body, *field_reader(keys), "};", "",
        "// The one Keys object (its table is case_keys(), parameters.hpp).",
        "const Keys& keys();", "", f"}} // namespace revsph::{model}", ""])


def generate_source(data):
    """keys() and case_keys(), the table the registry and the key reference see."""
    model = data["model"]
    return "\n".join([
        f"// Generated by tools/keygen/generate_case_keys.py from models/{model}/keys.toml: edit "
        "that file.",
        f'#include "models/{model}/case_keys.hpp"', "", f"namespace revsph::{model} {{", "",
        "const Keys& keys() {", "  static const Keys declared;", "  return declared;", "}", "",
        "const KeyTable& case_keys() {", "  return keys().table();", "}", "",
        f"}} // namespace revsph::{model}", ""])


def text_expression(text, parameters):
    """A C++ string expression: "@name" is the parameter itself; "{name}" inside a text is spliced
    in."""
    if text.startswith("@"):
        if text[1:] not in parameters:
            raise KeyFileError(f"{text}: no such parameter")
        return text[1:]
    parts = re.split(r"\{(\w+)\}", text)
    pieces = []
    for index, part in enumerate(parts):
        if index % 2 == 1:
            if part not in parameters:
                raise KeyFileError(f"{{{part}}}: no such parameter")
            pieces.append(part)
        elif part:
            pieces.append(cpp(part))
    if not pieces:
        return cpp("")
    if len(pieces) > 1 and pieces[0].startswith('"'):
        pieces[0] = f"std::string({pieces[0]})"
    return " + ".join(pieces)


def generate_core(data):
    """The core readers' key groups (core/keys.toml): each a function returning its declarations,
    or the common table."""
    lines = ["// Generated by tools/keygen/generate_case_keys.py from core/keys.toml: edit that file.",
             '#include "core/case_keys.hpp"', '#include "core/particle_discretisation.hpp"', "",
             "#include <string>", "#include <vector>", "", "namespace revsph {", ""]
    for group in data["group"]:
        function = group["function"]
        texts = group.get("text_parameters", [])
        lists = group.get("list_parameters", [])
        declarations = [declaration(key, texts, lists) for key in group["key"]]
        if "table" in group:
            lines += [f"const KeyTable& {function}() {{",
                      "  static const KeyTable table = [] {",
                      f"    KeyTable t({cpp(group['table'])});",
                      *[f"    t.add({d});" for d in declarations],
                      "    return t;", "  }();", "  return table;", "}", ""]
        else:
            parameters = [f"const std::string& {t}" for t in texts] + \
                         [f"const std::vector<std::string>& {name}" for name in lists]
            lines += [f"std::vector<KeyDecl> {function}({', '.join(parameters)}) {{",
                      "  return {", *[f"      {d}," for d in declarations], "  };", "}", ""]
    lines += ["} // namespace revsph", ""]
    return "\n".join(lines)


def main():
    arguments = sys.argv[1:]
    core = arguments[:1] == ["--core"]
    if core:
        arguments = arguments[1:]
    if len(arguments) != (2 if core else 3):
        sys.exit(__doc__)
    source = arguments[0]
    try:
        with open(source, "rb") as file:
            data = tomllib.load(file)
        if core:
            write(arguments[1], generate_core(data))
        else:
            write(arguments[1], generate(data))
            write(arguments[2], generate_source(data))
    except (tomllib.TOMLDecodeError, KeyFileError) as error:
        sys.exit(f"{source}: {error}")
    except KeyError as missing:
        sys.exit(f"{source}: {missing} missing")


def write(target, text):
    with open(target, "w") as file:
        file.write(text)


if __name__ == "__main__":
    main()
