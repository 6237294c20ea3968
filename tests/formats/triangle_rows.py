"""The rows of a file in Triangle's formats, for the format tests."""


def triangle_rows(path):
    """The rows of a Triangle file as lists of number strings, comments gone."""
    rows = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                rows.append(line)
    return rows
