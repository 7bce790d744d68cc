#!/usr/bin/env python3
"""Generates src/plan/kb/wordnet.txt from WordNet 3.0 (Debian's `wordnet-base`,
/usr/share/wordnet, Princeton's WordNet 3.0 licence; the notice is copied into the output).

Two tables, both small:
- `kind`: a noun the knowledge base lacks -> the knowledge-base category its nearest
  hypernym names (first sense, at most MAX_UP steps up), or a size class (`small`, `large`)
  from SIZE_CLASSES when no category is met. "owl" -> small, "chesterfield" -> sofa.
- `keep`: nouns ending in "s" that are singular (their "s"-less form is no noun): "dais".
- `irregular`: irregular plurals (WordNet's noun.exc) that rules get wrong: "mice" -> "mouse".
- `noun`: words that are nouns and never adjectives, with a tagged sense (in use): "tape",
  "hamster", "information"; before an unknown head noun they name its kind with it.
- `person`: nouns in use whose first sense is a person ("teacher", "mechanic", "groomer"):
  an object word said before one names whom the person works with ("a piano teacher's
  studio"), not an object.

Run from the repository root: python3 scripts/wordnet_kinds.py [WORDNET_DIR]
"""
import os
import re
import sys

from wordnet_licence import licence

WN = sys.argv[1] if len(sys.argv) > 1 else "/usr/share/wordnet"
OUT = "src/plan/kb/wordnet.txt"
MAX_UP = 4
# hypernym lemma -> size class, for nouns no category covers (first match going up wins)
SIZE_CLASSES = {
    "bird": "small", "mammal": "medium", "reptile": "small", "fish": "small",
    "container": "small", "device": "small", "instrument": "small", "utensil": "small",
    "decoration": "small", "sculpture": "medium", "toy": "small", "vessel": "small",
    "vehicle": "large", "craft": "large", "machine": "medium",
    "furniture": "medium", "equipment": "medium", "tree": "large", "shrub": "medium",
    "flower": "small", "rock": "medium", "book": "small", "weapon": "small",
}
# hypernym lemma -> knowledge-base category that stands for any kind of it, for nouns no
# nearer category covers (checked on the same way up as SIZE_CLASSES, before them): a giraffe
# or a deer is drawn and sized as a hoofed animal, not as a box (smaller mammals, people
# among them, keep their size class)
BROAD_CATEGORIES = {"ungulate": "hoofed animal"}


def kb_names():
    names = {}
    for line in open("src/plan/kb/objects.txt"):
        if line.startswith("#") or "|" not in line:
            continue
        f = [x.strip() for x in line.split("|")]
        cat = f[0]
        names[cat] = cat
        for s in f[1].split(","):
            if s.strip():
                names.setdefault(s.strip(), cat)
    return names


def read_data():
    syn = {}
    for line in open(os.path.join(WN, "data.noun")):
        if line.startswith(" "):
            continue
        f = line.split(" | ")[0].split()
        off, n = f[0], int(f[3], 16)
        lemmas = [re.sub(r"\(.*\)$", "", f[4 + 2 * i]).lower().replace("_", " ") for i in range(n)]
        k = 4 + 2 * n
        p = int(f[k])
        ups = [f[k + 1 + 4 * i + 1] for i in range(p) if f[k + 1 + 4 * i] in ("@", "@i")]
        syn[off] = (lemmas, ups)
    return syn


def first_senses():
    first = {}
    for line in open(os.path.join(WN, "index.noun")):
        if line.startswith(" "):
            continue
        f = line.split()
        lemma = f[0].replace("_", " ")
        n_syn = int(f[2])
        first[lemma] = f[-n_syn]
    return first


def index_lemmas(name):
    """Single-word lemmas of a WordNet index file with their tagged sense counts."""
    out = {}
    for line in open(os.path.join(WN, name)):
        if line.startswith(" "):
            continue
        f = line.split()
        p_cnt = int(f[3])
        out[f[0]] = int(f[5 + p_cnt])
    return out


def kind_of(off, syn, names):
    """The category of the nearest hypernym the knowledge base names (the synset's own other
    lemmas last: they are often looser than its hypernym), else a size class."""
    level = list(syn[off][1])
    for _ in range(MAX_UP):
        nxt = []
        for o in level:
            lemmas, ups = syn[o]
            for lm in lemmas:
                if lm in names:
                    return names[lm]
            nxt += ups
        level = nxt
    for lm in syn[off][0]:
        if lm in names:
            return names[lm]
    level = [off]
    while level:
        nxt = []
        for o in level:
            lemmas, ups = syn[o]
            for lm in lemmas:
                if lm in BROAD_CATEGORIES and BROAD_CATEGORIES[lm] in names:
                    return names[BROAD_CATEGORIES[lm]]
                if lm in SIZE_CLASSES:
                    return "size " + SIZE_CLASSES[lm]
            nxt += ups
        level = nxt
    return None


def physical(off, syn):
    """Whether the synset is under physical entity and not a person, place or substance."""
    seen, level = set(), [off]
    bad = {"person", "location", "substance", "body part", "food", "abstraction"}
    ok = False
    while level:
        nxt = []
        for o in level:
            if o in seen:
                continue
            seen.add(o)
            lemmas, ups = syn[o]
            if bad & set(lemmas):
                return False
            if "whole" in lemmas or "object" in lemmas:
                ok = True
            nxt += ups
        level = nxt
    return ok





def is_person(off, syn, person):
    """Whether the synset is a kind of person (person.n.01 among its hypernyms)."""
    seen, level = set(), [off]
    while level:
        nxt = []
        for o in level:
            if o in seen:
                continue
            if o == person:
                return True
            seen.add(o)
            nxt += syn[o][1]
        level = nxt
    return False


def main():
    names = kb_names()
    syn = read_data()
    first = first_senses()
    kinds = {}
    for lemma, off in first.items():
        if lemma in names or not re.fullmatch(r"[a-z][a-z -]*", lemma) or " " in lemma:
            continue
        if not physical(off, syn):
            continue
        k = kind_of(off, syn, names)
        if k:
            kinds[lemma] = k
    keep = sorted(w for w in first if re.fullmatch(r"[a-z]+s", w) and not w.endswith("ss")
                  and w[:-1] not in first and w not in names and physical(first[w], syn))
    # nouns that are no adjectives and that people use (WordNet's tagged sense count): said
    # before an unknown head noun they name its kind with it ("a tape dispenser")
    adjectives = set(index_lemmas("index.adj"))
    nouns = sorted(w for w, tagged in index_lemmas("index.noun").items()
                   if tagged > 0 and re.fullmatch(r"[a-z]+", w) and w not in adjectives)
    people = sorted(w for w, tagged in index_lemmas("index.noun").items()
                    if tagged > 0 and re.fullmatch(r"[a-z]+", w) and w not in names
                    and w in first and is_person(first[w], syn, first["person"]))
    irregular = {}
    for line in open(os.path.join(WN, "noun.exc")):
        f = line.split()
        if len(f) == 2 and re.fullmatch(r"[a-z]+", f[0]) and f[1] in first and f[0] != f[1] + "s":
            irregular[f[0]] = f[1]
    with open(OUT, "w") as o:
        o.write("# Generated by scripts/wordnet_kinds.py from WordNet 3.0; do not edit by hand.\n")
        # the licence asks for its notice, statements and disclaimer on every copy: taken
        # whole from the package's copyright file
        for line in licence():
            o.write(f"# {line}".rstrip() + "\n")
        o.write("# kind NOUN | CATEGORY or size CLASS; keep NOUN (singular ending in s); irregular PLURAL | SINGULAR; noun WORD; person WORD\n")
        for w in sorted(kinds):
            o.write(f"kind {w} | {kinds[w]}\n")
        for w in keep:
            o.write(f"keep {w}\n")
        for w in sorted(irregular):
            o.write(f"irregular {w} | {irregular[w]}\n")
        for w in nouns:
            o.write(f"noun {w}\n")
        for w in people:
            o.write(f"person {w}\n")
    print(f"{len(kinds)} kinds, {len(keep)} keep, {len(irregular)} irregular, {len(nouns)} nouns, {len(people)} people -> {OUT}")


main()
