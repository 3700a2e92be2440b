#!/usr/bin/python3
"""No library whose values reach the state calls the C library's transcendental functions.

glibc's exp, log, pow, sin, ... are not correctly rounded and glibc picks a variant per CPU (with
or without FMA): their last bits follow the machine. Physics and set-up call
fixedpoint/deterministic_math.hpp instead. This test lists the undefined symbols of every object
of the given static libraries (nm) and fails on any libm transcendental, so a new std::exp in a
model fails here rather than as a hash that differs on another CPU.

  deterministic_math_test.py NM CONTROL.a LIBRARY.a [LIBRARY.a ...]

CONTROL.a is a library that does call libm (the analysis library, whose values never reach the
state): the listing must find its calls, or the check itself is broken.
"""
import pathlib
import subprocess
import sys
import unittest

TRANSCENDENTALS = {
    name + suffix
    for name in ("exp", "exp2", "exp10", "expm1", "log", "log2", "log10", "log1p", "pow", "sin",
                 "cos", "tan", "sincos", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh",
                 "asinh", "acosh", "atanh", "hypot", "cbrt", "erf", "erfc", "lgamma", "tgamma")
    for suffix in ("", "f", "l")
}

# Calls that never decide a value of the state, each with the reason.
ALLOWED = {
    # CGAL's point-in-mesh test casts a ray in a pseudo-random direction (its Random draws use
    # log and sin/cos); exact predicates decide inside or outside whatever that direction is.
    ("revsph_stl", "stl_region.cpp.o"): {"log", "sincos"},
}


def library_name(path):
    return pathlib.Path(path).name.removeprefix("lib").removesuffix(".a")


def transcendental_calls(nm, archive):
    """{object file: set of libm transcendentals it calls} for one static library."""
    listing = subprocess.run([nm, "-A", "-u", archive], capture_output=True, text=True, check=True)
    calls = {}
    for line in listing.stdout.splitlines():
        location, _, symbol = line.rpartition(" ")
        symbol = symbol.split("@")[0]
        if symbol in TRANSCENDENTALS:
            member = location.rstrip(": U").split(":")[1]
            calls.setdefault(member, set()).add(symbol)
    return calls


class DeterministicMath(unittest.TestCase):
    def test_no_libm_transcendental_reaches_the_state(self):
        found = []
        for archive in ARCHIVES:
            library = library_name(archive)
            for member, symbols in transcendental_calls(NM, archive).items():
                left = symbols - ALLOWED.get((library, member), set())
                if left:
                    found.append("%s(%s): %s" % (library, member, " ".join(sorted(left))))
        self.assertEqual(found, [], "call revsph::dmath (fixedpoint/deterministic_math.hpp)")

    def test_the_listing_finds_the_calls_of_a_library_that_makes_them(self):
        found = set().union(*transcendental_calls(NM, CONTROL).values())
        self.assertTrue({"exp", "log"} <= found, found)


if __name__ == "__main__":
    NM, CONTROL = sys.argv[1:3]
    ARCHIVES = sys.argv[3:]
    unittest.main(argv=sys.argv[:1])
