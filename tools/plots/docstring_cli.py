"""The command line of a plotting script from its module docstring, so --help and the docstring
cannot drift apart: first paragraph = description, second = "Usage: ..." line(s), the rest =
epilog."""

import argparse


def parser_from_docstring(docstring):
    head, usage, *details = docstring.split("\n\n")
    return argparse.ArgumentParser(description=head, epilog="\n\n".join(details),
                                   usage=usage.removeprefix("Usage: "),
                                   formatter_class=argparse.RawDescriptionHelpFormatter)
