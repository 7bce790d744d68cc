"""The WordNet licence paragraph both WordNet scripts copy into what they generate."""
import sys

LICENCE = "/usr/share/doc/wordnet-base/copyright"


def licence():
    """The WordNet licence paragraph of Debian's copyright file, as lines."""
    out, inside = [], False
    for line in open(LICENCE):
        if "provided to you, the LICENSEE" in line:
            inside = True
        if inside:
            if not line.strip():
                break
            t = line.strip()
            out.append("" if t == "." else t)
    if not out:
        sys.exit(f"no WordNet licence found in {LICENCE}")
    return out
