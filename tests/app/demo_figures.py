# SPDX-License-Identifier: LGPL-2.1-or-later
"""The demo's printed figures as the README and docs/freecad-app.md quote them.

Each quote sits between the lines

    <!-- demo figures: ... -->          (or "<!-- demo figures (all): ... -->")
    <!-- end of demo figures -->

and holds lines of the summary samples/demo prints (in a ``` block). A quote marked "(all)" is
the whole summary; another picks lines of it by their label ("  sharp lines", "  points", ...).
The time line's seconds differ from run to run and are not compared.

Update the quotes from a run of the demo (from the repository's top folder):

    FEATURELINES_DEMO_SHOW=none samples/demo build | python3 tests/app/demo_figures.py --write

test_demo_figures.py runs the demo and fails when a quote differs from what it prints.
"""

import re
import sys

QUOTING_FILES = ("README.md", "docs/freecad-app.md")
BEGIN = re.compile(r"^<!-- demo figures( \(all\))?:.*-->$")
END = "<!-- end of demo figures -->"
TIME = re.compile(r"^(  time\s+)[0-9.]+ s$")


def summary(output):
    """The summary lines of the demo's output: from "Feature lines of" to "  patch clouds"."""
    lines = output.splitlines()
    first = next((i for i, l in enumerate(lines) if l.startswith("Feature lines of ")
                  and not l.endswith("...")), None)
    if first is None:
        raise ValueError("the demo printed no summary (no line 'Feature lines of NAME')")
    last = next((i for i in range(first, len(lines)) if lines[i].startswith("  patch clouds")),
                None)
    if last is None:
        raise ValueError("the demo's summary has no '  patch clouds' line")
    return lines[first:last + 1]


def comparable(line):
    """The line with the seconds of the time line left out."""
    return TIME.sub(r"\1<seconds> s", line)


def label(line):
    """What a summary line is about: the words before the column of values."""
    return re.split(r"\s{2,}", line.strip(), maxsplit=1)[0]


def quotes(text):
    """[(first line index, end index, whole)]: the quoted lines of each marked block (without the
    ``` fences) as line index ranges of `text`'s lines."""
    lines = text.splitlines()
    found = []
    i = 0
    while i < len(lines):
        match = BEGIN.match(lines[i])
        if not match:
            i += 1
            continue
        end = next((j for j in range(i + 1, len(lines)) if lines[j] == END), None)
        if end is None:
            raise ValueError("line %d: a demo figures quote without '%s'" % (i + 1, END))
        body = [j for j in range(i + 1, end) if not lines[j].startswith("```")]
        if not body:
            raise ValueError("line %d: an empty demo figures quote" % (i + 1))
        found.append((body[0], body[-1] + 1, bool(match.group(1))))
        i = end + 1
    return found


def differences(text, printed):
    """One message per quoted line of `text` that is not what the demo printed (`printed`: its
    summary lines): the whole summary for an "(all)" quote, otherwise the printed lines in the
    same order."""
    lines = text.splitlines()
    messages = []
    wanted = [comparable(l) for l in printed]
    for first, end, whole in quotes(text):
        quoted = [comparable(l) for l in lines[first:end]]
        if whole:
            if quoted != wanted:
                messages.append("lines %d-%d quote\n%s\nbut the demo printed\n%s" %
                                (first + 1, end, "\n".join(quoted), "\n".join(wanted)))
            continue
        at = 0
        for k, line in enumerate(quoted):
            while at < len(wanted) and wanted[at] != line:
                at += 1
            if at == len(wanted):
                messages.append("line %d quotes '%s'; the demo printed '%s'" %
                                (first + k + 1, line, next(
                                    (w for w in wanted if label(w) == label(line)), "no such line")))
                at = 0
    return messages


def rewritten(text, printed):
    """`text` with every quote replaced by the printed summary (all of it, or the lines of the
    same labels)."""
    lines = text.splitlines()
    for first, end, whole in reversed(quotes(text)):
        if whole:
            new = list(printed)
        else:
            by_label = {label(l): l for l in printed}
            new = [by_label.get(label(l), l) for l in lines[first:end]]
        lines[first:end] = new
    return "\n".join(lines) + ("\n" if text.endswith("\n") else "")


def main():
    if sys.argv[1:] != ["--write"]:
        sys.stderr.write(__doc__)
        return 2
    printed = summary(sys.stdin.read())
    for name in QUOTING_FILES:
        with open(name, encoding="utf-8") as f:
            text = f.read()
        new = rewritten(text, printed)
        if new != text:
            with open(name, "w", encoding="utf-8") as f:
                f.write(new)
            print("updated the demo figures in %s" % name)
    return 0


if __name__ == "__main__":
    sys.exit(main())
