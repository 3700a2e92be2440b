"""A benchmark's Markdown record: printed, and written to --output when one is given."""


def emit(lines, output=None):
    text = "\n".join(lines) + "\n"
    print(text)
    if output:
        with open(output, "w") as f:
            f.write(text)
