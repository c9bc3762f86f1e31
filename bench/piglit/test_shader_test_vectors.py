#!/usr/bin/env python3
"""The piglit vector reader against a hand-written sample and bad input."""
import json
import os
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import shader_test_vectors  # noqa: E402

SAMPLE = os.path.join(HERE, "testdata", "refract-sample.shader_test")
READER = os.path.join(HERE, "shader_test_vectors.py")

# The sample's three draws after all three uniforms are set (its first draw,
# before them, gives none), read by hand from the file.
EXPECTED = [
    {"fn": "refract", "I": [0.6, -0.8, 0.0], "N": [0.0, 1.0, 0.0], "eta": 0.75},
    {"fn": "refract", "I": [0.6, -0.8, 0.0], "N": [0.0, 1.0, 0.0], "eta": 1.5},
    {"fn": "refract", "I": [-0.0, -1.0, 0.0], "N": [0.0, 1.0, 0.0], "eta": 1.5},
]

REFLECT = """[vertex shader]
uniform vec2 a;
uniform vec2 b;
void main() { gl_Position = vec4(reflect(a, b), 0.0, 1.0); }
[test]
uniform vec2 a 1 -1
uniform vec2 b 0 1
draw rect -1 -1 2 2
"""


def run_reader(*paths):
    return subprocess.run([sys.executable, READER, *paths], capture_output=True, text=True)


class ShaderTestVectors(unittest.TestCase):
    def test_sample_gives_its_vectors_as_eval_lines(self):
        result = run_reader(SAMPLE)
        self.assertEqual(result.returncode, 0, result.stderr)
        lines = [json.loads(line) for line in result.stdout.splitlines()]
        self.assertEqual(lines, EXPECTED)
        # -0.0 stays negative: refract's sign matters to the oracle.
        self.assertTrue(str(lines[2]["I"][0]).startswith("-"))

    def test_each_vector_names_its_draw_line(self):
        with open(SAMPLE, encoding="utf-8") as file:
            found = shader_test_vectors.vectors(file.read(), "sample")
        self.assertEqual([v["where"] for v in found], ["sample:28", "sample:30", "sample:32"])

    def test_reflect_has_no_eta(self):
        found = shader_test_vectors.vectors(REFLECT, "r")
        self.assertEqual(json.loads(shader_test_vectors.eval_line(found[0])),
                         {"fn": "reflect", "I": [1.0, -1.0], "N": [0.0, 1.0]})

    def test_constant_arguments_give_no_vectors(self):
        text = REFLECT.replace("reflect(a, b)", "reflect(vec2(1.0), b)")
        self.assertEqual(shader_test_vectors.vectors(text, "c"), [])

    def test_a_value_that_is_not_a_number_stops_with_file_and_line(self):
        bad = SAMPLE + ".bad"
        with open(SAMPLE, encoding="utf-8") as file:
            text = file.read().replace("0.6 -0.8 0.0", "0.6 x 0.0")
        with open(bad, "w", encoding="utf-8") as file:
            file.write(text)
        try:
            result = run_reader(bad)
        finally:
            os.remove(bad)
        self.assertEqual(result.returncode, 2)
        self.assertEqual(result.stdout, "")
        self.assertIn(f"{bad}:25: 'x' is not a number", result.stderr)

    def test_a_wrong_component_count_stops(self):
        text = REFLECT.replace("uniform vec2 b 0 1", "uniform vec2 b 0 1 2")
        with self.assertRaisesRegex(shader_test_vectors.ParseError, r"^r:7: vec2 b needs 2"):
            shader_test_vectors.vectors(text, "r")

    def test_a_file_without_a_test_section_stops(self):
        result = run_reader(READER)
        self.assertEqual(result.returncode, 2)
        self.assertIn("no [test] section", result.stderr)


if __name__ == "__main__":
    unittest.main()
