#!/usr/bin/python3
"""tools/keygen/generate_case_keys.py, which turns a model's keys.toml into its C++ Keys struct:

- every declaration kind becomes the member the README promises (checks, choices, core groups,
  scales, keys read elsewhere, read_fields);
- a bad keys.toml (an unknown type or check, a missing field, a bool choice of three values)
  stops the build with one line naming the file and the key;
- every model's keys.toml is well formed: unique member names and paths, a literal default for
  every choice, every `field` on a key the generated reader can read.

Usage: keygen_test.py [unittest options]   (plain Python, no revsph binary)
"""

import os
import subprocess
import sys
import tempfile
import tomllib
import unittest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "tools", "keygen"))

import generate_case_keys as keygen  # noqa: E402

MODELS = sorted(name for name in os.listdir(os.path.join(ROOT, "models"))
                if os.path.exists(os.path.join(ROOT, "models", name, "keys.toml")))


def header_of(text):
    return keygen.generate(tomllib.loads(text))


class Declarations(unittest.TestCase):
    def test_number_with_interval_check_and_field(self):
        header = header_of('model = "m"\n[[key]]\nname = "gamma"\ntype = "number"\n'
                           'path = "physics.gamma"\nunit = "1"\ndefault = "7"\nmeaning = "g"\n'
                           'check = "[1, 20]"\nfield = "eos.gamma"\n')
        self.assertIn('const Key<double> gamma = number("physics.gamma", "1", "7", "g", '
                      'within<double>(1.0, true, 20.0, true, "must be in [1, 20]"));', header)
        self.assertIn("p.eos.gamma = gamma.read(case_file);", header)

    def test_core_checks_and_open_infinite_ends(self):
        header = header_of(
            'model = "m"\n'
            '[[key]]\nname = "a"\ntype = "number"\npath = "x.a"\nunit = "m"\ndefault = "required"\n'
            'meaning = ""\ncheck = "> 0"\n'
            '[[key]]\nname = "b"\ntype = "number"\npath = "x.b"\nunit = "m"\ndefault = "0"\n'
            'meaning = ""\ncheck = ">= 0"\nzero_means = "off"\n'
            '[[key]]\nname = "c"\ntype = "number"\npath = "x.c"\nunit = "s"\ndefault = "none"\n'
            'meaning = ""\ncheck = "(0, inf]"\nmessage = "must be > 0"\n'
            '[[key]]\nname = "n"\ntype = "integer"\npath = "x.n"\ndefault = "1"\nmeaning = ""\n'
            'check = "[0, inf)"\n')
        self.assertIn('"required", "", positive_or_why);', header)
        self.assertIn('non_negative("off"));', header)
        self.assertIn('within<double>(0.0, false, std::nullopt, true, "must be > 0")', header)
        self.assertIn('within<std::int64_t>(0, true, std::nullopt, false, "must be >= 0")', header)

    def test_choices_map_to_bool_or_enumerators(self):
        header = header_of(
            'model = "m"\n'
            '[[key]]\nname = "on"\ntype = "choice"\npath = "f.mode"\ndefault = "passive"\n'
            'meaning = ""\nvalues = ["passive", "active"]\nenum = "bool"\n'
            '[[key]]\nname = "field"\ntype = "choice"\npath = "initial.field"\n'
            'default = "required"\nmeaning = ""\nvalues = ["rest", "gresho"]\n'
            'enum = "InitialField"\nenumerators = ["rest", "gresho_vortex"]\n')
        self.assertIn('choice<bool>("f.mode", "\\"passive\\"", "", {{"passive", false}, '
                      '{"active", true}});', header)
        self.assertIn('"required", "", {{"rest", InitialField::rest}, '
                      '{"gresho", InitialField::gresho_vortex}});', header)

    def test_core_groups_scales_and_keys_read_elsewhere(self):
        header = header_of(
            'model = "m"\n'
            '[[key]]\ncore = "particle_block"\nkinds = ["fluid", "wall"]\n'
            '[[key]]\ncore = "wall"\nargs = ["eq. 7"]\n'
            '[[key]]\nname = "velocity_exponent"\ntype = "scale"\nquantity = "velocity"\n'
            'magnitude = "c"\nbits = 50\nmeaning = "v"\n'
            '[[key]]\nname = "centre"\ntype = "numbers"\npath = "initial.centre"\nunit = "m"\n'
            'default = "the origin"\nmeaning = "c"\n')
        self.assertIn('declare(particle_block_case_keys({"fluid", "wall"}))', header)
        self.assertIn('declare(wall_case_keys("eq. 7"))', header)
        self.assertIn('const ScaleKey velocity_exponent = scale("velocity", "c", 50, "v", "");',
                      header)
        self.assertIn('const std::string centre = declare({"initial.centre", KeyType::numbers, '
                      '"m", "the origin", "c"});', header)


class CoreGroups(unittest.TestCase):
    def test_parameters_spliced_into_texts_and_values(self):
        source = keygen.generate_core(tomllib.loads(
            '[[group]]\nfunction = "wall_case_keys"\ntext_parameters = ["equation"]\n'
            '[[group.key]]\npath = "wall.epsilon"\ntype = "number"\nunit = "m"\n'
            'default = "1e-6"\nmeaning = "eps of ({equation}); >= 0"\n'
            '[[group]]\nfunction = "particle_block_case_keys"\nlist_parameters = ["kinds"]\n'
            '[[group.key]]\npath = "particles[].kind"\ntype = "string"\ndefault = "required"\n'
            'meaning = "which set"\nvalues = "@kinds"\n'
            '[[group]]\nfunction = "common_case_keys"\ntable = "common"\n'
            '[[group.key]]\npath = "model"\ntype = "string"\ndefault = "required"\n'
            'meaning = "the model"\n'))
        self.assertIn('std::vector<KeyDecl> wall_case_keys(const std::string& equation) {', source)
        self.assertIn('std::string("eps of (") + equation + "); >= 0"}', source)
        self.assertIn('{"particles[].kind", KeyType::string, "-", "required", "which set", kinds}',
                      source)
        self.assertIn('KeyTable t("common");', source)
        with self.assertRaises(keygen.KeyFileError):
            keygen.generate_core(tomllib.loads(
                '[[group]]\nfunction = "f"\n[[group.key]]\npath = "a"\ntype = "number"\n'
                'default = "0"\nmeaning = "{nobody}"\n'))

    def test_core_keys_file_generates(self):
        with open(os.path.join(ROOT, "core", "keys.toml"), "rb") as file:
            data = tomllib.load(file)
        self.assertEqual([g["function"] for g in data["group"]],
                         ["common_case_keys", "domain_case_keys", "particle_block_case_keys",
                          "particle_discretisation_case_keys", "wall_case_keys"])
        keygen.generate_core(data)


class BadFiles(unittest.TestCase):
    def failure_of(self, text):
        with tempfile.TemporaryDirectory() as folder:
            source = os.path.join(folder, "keys.toml")
            with open(source, "w") as file:
                file.write(text)
            result = subprocess.run(
                [sys.executable, os.path.join(ROOT, "tools", "keygen", "generate_case_keys.py"),
                 source, os.path.join(folder, "k.hpp"), os.path.join(folder, "k.cpp")],
                capture_output=True, text=True)
        self.assertNotEqual(result.returncode, 0)
        self.assertEqual(len(result.stderr.strip().splitlines()), 1, result.stderr)
        self.assertIn("keys.toml", result.stderr)
        return result.stderr

    def test_unknown_check(self):
        self.assertIn("x.a: check 'positive'", self.failure_of(
            'model = "m"\n[[key]]\nname = "a"\ntype = "number"\npath = "x.a"\nunit = "m"\n'
            'default = "1"\nmeaning = ""\ncheck = "positive"\n'))

    def test_unknown_type_missing_field_and_bad_choice(self):
        self.assertIn("type 'real' unknown", self.failure_of(
            'model = "m"\n[[key]]\nname = "a"\ntype = "real"\npath = "x.a"\ndefault = "1"\n'
            'meaning = ""\n'))
        self.assertIn("'meaning' missing", self.failure_of(
            'model = "m"\n[[key]]\nname = "a"\ntype = "boolean"\npath = "x.a"\ndefault = "true"\n'))
        self.assertIn("two values", self.failure_of(
            'model = "m"\n[[key]]\nname = "a"\ntype = "choice"\npath = "x.a"\ndefault = "p"\n'
            'meaning = ""\nvalues = ["p", "q", "r"]\nenum = "bool"\n'))
        self.assertIn("Expected", self.failure_of('model = "m"\n[[key]\n'))


class ModelKeyFiles(unittest.TestCase):
    def test_every_model_has_its_keys_file(self):
        self.assertEqual(MODELS, ["entropic", "shtc", "superfluid", "two_fluid", "wcsph"])

    def test_names_and_paths_unique_choices_literal_fields_readable(self):
        for model in MODELS:
            with self.subTest(model=model):
                with open(os.path.join(ROOT, "models", model, "keys.toml"), "rb") as file:
                    data = tomllib.load(file)
                self.assertEqual(data["model"], model)
                names = [k["name"] for k in data["key"] if "name" in k]
                paths = [k["path"] for k in data["key"] if "path" in k]
                self.assertEqual(len(names), len(set(names)))
                self.assertEqual(len(paths), len(set(paths)))
                for key in data["key"]:
                    if key.get("type") == "choice" and key["default"] != "required":
                        self.assertIn(key["default"], key["values"], key["path"])
                    if "field" in key:
                        where = key.get("path", key["name"])
                        self.assertFalse(key.get("declared_only"), where)
                        literal = key.get("default") in ("required", None) or \
                            key["type"] in ("choice", "splitting") or \
                            keygen.is_literal(key["default"], key["type"])
                        self.assertTrue(literal, f"{where}: read_fields needs a literal default "
                                        "or a required key")
                keygen.generate(data)


if __name__ == "__main__":
    unittest.main()
