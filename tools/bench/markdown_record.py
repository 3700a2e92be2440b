"""A benchmark's Markdown record: printed, and written to --output when one is given."""


def emit(lines, output=None):
    text = "\n".join(lines) + "\n"
    print(text)
    if output:
        with open(output, "w") as f:
            f.write(text)


def hashes_line(hashes, summary):
    """The closing line of a record of runs: how many distinct final hashes, and the commit."""
    return (f"final hashes over every run: {len(hashes)} distinct "
            f"({', '.join(h[:16] for h in sorted(hashes))}); commit "
            f"{summary['build']['git_commit']}")
