#!/usr/bin/env python3
"""Throw seeded random and mutated inputs at the sphere-row executable and
check its contract on every one of them.

The contract: an input is either answered, exit status 0 with well-formed
output on stdout (`key value` lines whose numbers are finite, with the event
table as TSV when asked for; with print=, the lines it names and no other)
and on stderr nothing but progress lines and
notes (`sphere-row: progress: ...`, `sphere-row: note (the run goes on):
...`, each one line of plain ASCII), or refused, exit status 2
with nothing on stdout and exactly one line of plain ASCII on stderr that
begins with `sphere-row: `. Never a signal, never a time-out, never `nan`,
`inf` or `***`, never another exit status.

Inputs: key=value pairs with values at the edges of every range (real(8)'s
and real(16)'s largest, smallest normal and subnormal numbers, the bounds of
each key written with more digits than real(16) holds), numbers that are not
numbers, words with blanks around them, control bytes and bytes beyond ASCII,
long lists of the right and wrong lengths; mutations (bytes flipped, cut,
doubled) of valid command lines; scene files, valid and mutated, with junk,
comments, long runs of line ends, given by name or on standard input; the
keys of any initial state (velocities, walls, a ring, a random gas, a
horizon) and tables of spheres (spheres=FILE), valid and mutated; paths
that are not regular files. Every input is made from the seed alone, so a
failure is reproduced by the same seed and count (each failure is also
printed with its arguments and file).

    python3 tools/fuzz.py --binary build/.../sphere-row --seed 1 --count 10000

Exit status: 0 if every input kept the contract within the time limit, 1 if
not (each breach is listed), 2 for bad options.
"""

import argparse
import concurrent.futures
import os
import random
import re
import subprocess
import sys
import tempfile
import time

PROGRAM = "sphere-row"

# every key of sphere-row and what its values may look like
SCENE_KEYS = ["p", "e", "d", "a", "gaps", "v0", "masses", "tol", "max_collisions",
              "calendar_from"]
# the keys of any initial state: velocities, walls, a ring, a random gas, a
# horizon (a table of spheres comes as a file: make_case)
STATE_KEYS = ["velocities", "wall_left", "wall_right", "e_wall", "ring", "gas", "density",
              "temperature", "seed", "t_max"]
KEYS = SCENE_KEYS + STATE_KEYS + ["events", "precision", "print"]
# the names print= takes: the answer's lines (v, x, y: every v<i>, x<i>, y<i>)
LINE_NAMES = ["collisions", "t_end", "t", "status", "precision", "certified", "not_dp", "answer",
              "v_bound", "collapses", "closed_form_limits", "limits_exact", "limits_certified",
              "limits_tolerance", "limits_bounded", "collapse", "separation_not_excluded_below",
              "collapse_spheres", "collapse_t", "separation_scale", "active", "v", "x", "y"]

# numbers at the edges: of real(16) (huge, tiny, subnormal), of real(8),
# of each key's range, written with more digits than real(16) holds
EDGE_NUMBERS = [
    "0", "-0", "+0", "0.0", "1", "-1", "0.5", ".5", "5.", "2", "0.2", "0.1", "1e0", "1d0",
    "1.18e4932", "1.19e4932", "1e4932", "1e4933", "1e5000", "-1e5000",
    "3.3621031431120935062626778173217526e-4932", "3.36e-4932", "3.37e-4932", "1e-4931",
    "1e-4932", "1e-4933", "1e-4940", "6.5e-4966", "1e-4966", "1e-5000", "1e-99999",
    "1.7976931348623157e308", "1.8e308", "1e308", "1e309", "2.2250738585072014e-308",
    "2.2e-308", "1e-308", "4.9e-324", "1e-400", "1e400",
    "1.00000000000000000000000000000000001", "0.99999999999999999999999999999999999999",
    "1.0000000000000000000000000000000000000000000000000000000000001",
    "-0.00000000000000000000000000000000000000001", "0.17157287525380990239662255158060",
    "0.1715728752538099023966225515806039", "1e-34", "1.93e-34", "1e99999999999999999999",
    "1e-99999999999999999999", "0." + "0" * 200 + "1", "1" + "0" * 300, "9" * 40,
    "2147483647", "2147483648", "-2147483648", "1000000", "1000001", "999999",
]
JUNK_NUMBERS = [
    "", "nan", "NaN", "inf", "-inf", "Infinity", "1-5", "1+2", "0x10", "1e", "1e+", "e5",
    ".", "-", "+", "--1", "1..2", "1.2.3", "1_16", "0.5q0", "1,5", "(1)", "1/2", "4*1",
    " 1", "1 ", "\t1", "1\n", "١", "½", "0.5\u00a0", "1e5.0", "0.5d", "0b101", "1 e5",
]
WORDS = ["yes", "no", "qp", "dp", "auto", "Yes", "NO", "yes ", " no", "qp ", " dp", "QP",
         "q", "", "auto,qp", "ye", "yess", "\tqp", "dp\n"]


def number(rng):
    """One number text: an edge, a junk text, or a random number."""
    roll = rng.random()
    if roll < 0.45:
        return rng.choice(EDGE_NUMBERS)
    if roll < 0.6:
        return rng.choice(JUNK_NUMBERS)
    mantissa = rng.choice(["%d", "%.3f", "%.17g", "%.40f"]) % rng.uniform(0, 10)
    if rng.random() < 0.5:
        mantissa += rng.choice("eEdD") + str(rng.randint(-5000, 5000))
    if rng.random() < 0.2:
        mantissa = "-" + mantissa
    return mantissa


def small_value(rng, key):
    """A value that keeps a run short: the scenes the fuzz means to finish."""
    if key == "p":
        return str(rng.choice([2, 3, 4, 5, 6, 8, 12, 16]))
    if key == "e":
        return rng.choice(["0", "0.1", "0.2", "0.5", "1", "%.6f" % rng.random()])
    if key in ("d", "a", "v0"):
        return rng.choice(["1", "0.5", "2", "1e-3", "1e3", "%.4g" % rng.uniform(0.01, 100)])
    if key == "tol":
        return rng.choice(["0", "1e-30", "1e-10", "1e-3"])
    if key == "max_collisions":
        return str(rng.randint(1, 3000))
    if key == "calendar_from":
        return str(rng.randint(2, 64))
    if key == "events":
        return rng.choice(["yes", "no"])
    if key in ("wall_left", "wall_right", "ring"):
        return rng.choice(["0", "0.5", "1", "3", "%.4g" % rng.uniform(0, 5)])
    if key == "e_wall":
        return rng.choice(["0", "0.3", "1", "%.6f" % rng.random()])
    if key == "gas":
        return rng.choice(["ring", "box", "no"])
    if key == "density":
        return rng.choice(["0.1", "0.5", "0.9", "%.4g" % rng.uniform(0.01, 0.99)])
    if key == "temperature":
        return rng.choice(["1", "0.01", "100", "%.4g" % rng.uniform(0.1, 10)])
    if key == "seed":
        return str(rng.randint(0, 2 ** 31 - 1))
    if key == "t_max":
        return rng.choice(["0.1", "1", "10", "%.4g" % rng.uniform(0.01, 30)])
    if key == "print":
        if rng.random() < 0.2:
            return "all"
        return ",".join(rng.sample(LINE_NAMES, rng.randint(1, 4)))
    return rng.choice(["qp", "dp", "auto"])


def value(rng, key, p):
    """A value for `key`: small and valid, at an edge, junk, or a list."""
    roll = rng.random()
    if key in ("masses", "gaps", "velocities"):
        n = p - 1 if key == "gaps" else p
        n = rng.choice([n, n, n, n - 1, n + 1, 0, 1, max(0, n * 3)])
        low = -5 if key == "velocities" else 0.1
        if roll < 0.5:
            return ",".join("%.4g" % rng.uniform(low, 10) for _ in range(n))
        return ",".join(number(rng) if rng.random() < 0.3 else "1" for _ in range(n))
    if key in ("events", "precision", "gas"):
        return rng.choice(WORDS) if roll < 0.4 else small_value(rng, key)
    if key == "print":
        # names twice, empty, in another case, beside all, or not names at all
        return rng.choice(WORDS + ["v,v", "v,,x", "v,", ",v", "V", "all,v", "v<i>", "v1",
                                   "print", "vx", " v", "v "]) if roll < 0.4 \
            else small_value(rng, key)
    if roll < 0.5:
        return small_value(rng, key)
    if key in ("p", "max_collisions", "calendar_from"):
        # integers at the edges, but none that makes a long run (see RUN_CAP)
        return rng.choice(["0", "1", "-1", "+4", "007", "4.0", "4e0", "2147483648",
                           "-2147483649", "99999999999999999999", "1000001", "3", "500",
                           "2000", "", "1e3", "0x10", "4 ", " 4"])
    return number(rng)


def junk_bytes(rng, n):
    """n random bytes, none of them NUL (an argument cannot hold one)."""
    return bytes(rng.randint(1, 255) for _ in range(n))


def mutate(rng, data):
    """data with a few bytes flipped, cut, doubled or inserted."""
    data = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        if not data:
            data += junk_bytes(rng, 1)
            continue
        i = rng.randrange(len(data))
        kind = rng.randrange(5)
        if kind == 0:
            data[i] = rng.randint(1, 255)
        elif kind == 1:
            del data[i:i + rng.randint(1, 4)]
        elif kind == 2:
            data[i:i] = data[i:i + rng.randint(1, 8)]
        elif kind == 3:
            data[i:i] = rng.choice([b"=", b",", b" ", b"e", b"-", b".", b"9", b"\t", b"\x7f",
                                    b"\xff", b"/", b"&", b"!", b"\n", b"*", b"("])
        else:
            data[i:i] = junk_bytes(rng, rng.randint(1, 6))
    return bytes(data)


def valid_pairs(rng):
    """A short valid-looking scene as key=value pairs."""
    p = int(small_value(rng, "p"))
    pairs = [("p", str(p))]
    for key in rng.sample(KEYS[1:], rng.randint(0, 5)):
        if key == "p" or key == "max_collisions":
            continue
        if key in ("masses", "gaps", "velocities"):
            n = p - 1 if key == "gaps" else p
            low = -5 if key == "velocities" else 0.2
            pairs.append((key, ",".join("%.3g" % rng.uniform(low, 5) for _ in range(n))))
        elif key == "a" and any(k == "gaps" for k, _ in pairs):
            continue
        else:
            pairs.append((key, small_value(rng, key)))
    if any(k == "gaps" for k, _ in pairs):
        pairs = [(k, v) for k, v in pairs if k != "a"]
    return pairs


def scene_file_text(rng, pairs):
    """A namelist group of the pairs, in any of the allowed layouts."""
    sep = rng.choice([", ", ",\n", " ", "\n  ", ",\t"])
    items = []
    for key, val in pairs:
        name = key.upper() if rng.random() < 0.2 else key
        if key in ("masses", "gaps") and rng.random() < 0.5:
            val = val.replace(",", rng.choice([", ", " ", ",\n    "]))
        items.append("%s = %s" % (name, val))
    head = "! a scene made by the fuzz\n" if rng.random() < 0.3 else ""
    lines = "\n" * rng.choice([0, 0, 1, 1000]) if rng.random() < 0.2 else ""
    return head + lines + rng.choice(["&scene ", "&SCENE\n"]) + sep.join(items) + " /\n"


class Case:
    """One input: the arguments and, if any, a scene file's bytes and whether it
    goes to standard input."""

    def __init__(self, args, file_bytes=None, stdin=False, table=False):
        self.args = args
        self.file_bytes = file_bytes
        self.stdin = stdin
        self.table = table


def make_case(rng, index):
    """The input number `index` of this seed."""
    kind = rng.random()
    if kind < 0.35:
        # random key=value pairs, keys and values from every pool
        p = rng.choice([2, 3, 4, 4, 6, 10])
        args = []
        for _ in range(rng.randint(0, 5)):
            key = rng.choice(KEYS + ["foo", "E", "", " e", "e ", "-e", "--help", "masses(2)"])
            args.append("%s=%s" % (key, value(rng, key, p)))
        if rng.random() < 0.1:
            args.append(rng.choice(["--", "-", "x", "", "=", "==", "e==1", "e=1=2"]))
        if rng.random() < 0.3:
            # the other precisions take the same values through other checks
            args.append(rng.choice(["precision=dp", "precision=auto"]))
        return Case([a.encode("utf-8", "surrogateescape") for a in args])
    if kind < 0.6:
        # a valid command line, mutated
        args = [("%s=%s" % kv).encode() for kv in valid_pairs(rng)]
        if args and rng.random() < 0.9:
            i = rng.randrange(len(args))
            args[i] = mutate(rng, args[i]).replace(b"\x00", b"")
        if rng.random() < 0.1:
            args.append(junk_bytes(rng, rng.randint(1, 40)))
        return Case(args)
    if kind < 0.9:
        # a scene file, valid or mutated, by name or on standard input
        text = scene_file_text(rng, valid_pairs(rng)).encode()
        roll = rng.random()
        if roll < 0.6:
            text = mutate(rng, text)
        elif roll < 0.7:
            text = junk_bytes(rng, rng.randint(1, 300))
        elif roll < 0.75:
            text = text + b"\x00" * rng.randint(1, 10)
        extra = []
        if rng.random() < 0.3:
            extra = [("%s=%s" % kv).encode() for kv in valid_pairs(rng)[1:2]]
        stdin = rng.random() < 0.3
        return Case(extra, file_bytes=text, stdin=stdin)
    if kind < 0.95:
        # a table of spheres (spheres=FILE), valid or mutated, with keys of a scene
        p = rng.choice([2, 3, 5, 8])
        x, rows = 0.0, ["x\tv\tm"]
        for _ in range(p):
            rows.append("%.6g\t%.6g\t%.4g" % (x, rng.uniform(-2, 2), rng.uniform(0.1, 5)))
            x += 1 + rng.choice([0.0, rng.uniform(0, 2)])
        text = ("\n".join(rows) + "\n").encode()
        if rng.random() < 0.6:
            text = mutate(rng, text)
        extra = [("%s=%s" % kv).encode() for kv in valid_pairs(rng)[1:3] if kv[0] != "p"]
        return Case(extra, file_bytes=text, table=True)
    # paths that are not scene files, and odd argument lists
    roll = rng.random()
    if roll < 0.5:
        path = rng.choice([b"/dev/null", b"/dev/zero", b"/dev/urandom", b"/", b".",
                           b"/no/such/file", b"-", b"--help", b"help", b"-h", b"--version"])
        return Case([path], stdin=path == b"-")
    return Case([junk_bytes(rng, rng.randint(1, 20)) for _ in range(rng.randint(1, 3))])


NUMBER = re.compile(rb"^-?\d\.\d+E[+-]\d+$")
# a velocity printed down to its bound's decade: 2.5E-01, or 3E-02, 0E-01
VELOCITY = re.compile(rb"^-?\d(\.\d+)?E[+-]\d+$")
LINE = re.compile(rb"^[a-z_]+[0-9]* \S.*$")


# what an answered run may write on stderr: a long run's progress lines and
# a long row's note on its event table, nothing that reads as a refusal
ALLOWED_STDERR = re.compile(rb"^sphere-row: (progress|note \(the run goes on\)): [ -~]*$")


def check_output(out, err, events, printed=None):
    """What breaks the contract in an answered run's output, or None;
    `printed`: the names print= asked for (None: every line)."""
    if err and (not err.endswith(b"\n") or
                not all(ALLOWED_STDERR.match(line) for line in err.split(b"\n")[:-1])):
        return "exit 0 with stderr other than progress lines and notes: %r" % err[:200]
    asked = (lambda name: True) if printed is None else (
        lambda name: re.sub(rb"^([vxy])\d+$", rb"\1", name).decode() in printed)
    if not out.endswith(b"\n") and not (printed is not None and out == b"" and not events):
        return "output does not end with a line end"
    if b"***" in out or re.search(rb"(?i)\b-?(nan|inf)\b", out):
        return "nan, inf or *** in the output"
    lines = out.split(b"\n")[:-1]
    keys = set()
    values = {}
    table = False
    for line in lines:
        if line.startswith(b"event\tkind\t"):
            table = True
            continue
        if table and b"\t" in line:
            fields = line.split(b"\t")
            if not all(NUMBER.match(f) for f in fields[4:]):
                return "a field of the event table is not a number: %r" % line[:200]
            continue
        if not LINE.match(line):
            return "malformed line: %r" % line[:200]
        key, val = line.split(b" ", 1)
        if not asked(key):
            return "a line print= did not ask for: %r" % line[:200]
        keys.add(key)
        values[key] = val
        if re.match(rb"^(t_end|collapse_t|[xy]\d+)$", key) and not NUMBER.match(val):
            return "not a number: %r" % line[:200]
        if re.match(rb"^v\d+$", key) and not VELOCITY.match(val):
            return "not a velocity: %r" % line[:200]
        if key == b"v_bound" and not NUMBER.match(val):
            return "v_bound not a number: %r" % line[:200]
    for need in (b"collisions", b"t_end", b"status", b"precision", b"answer", b"v_bound",
                 b"v1", b"x1", b"y1"):
        if need not in keys and asked(need):
            return "no line %s" % need.decode()
    if events and not table:
        return "events=yes without the event table"
    # a label is a proof: limits say whether the collapse is proven, an
    # unproven one how far the claim reaches, and a certified answer with
    # limits proves the collapse
    if b"collapses" in keys and asked(b"collapse"):
        if values.get(b"collapse") not in (b"proven", b"unproven"):
            return "collapse limits without a `collapse proven|unproven` line"
        if values[b"collapse"] == b"unproven" and b"separation_not_excluded_below" not in keys \
                and asked(b"separation_not_excluded_below"):
            return "collapse unproven without separation_not_excluded_below"
        if values.get(b"answer") in (b"exact", b"certified") and values[b"collapse"] != b"proven":
            return "answer %s with collapse unproven" % values[b"answer"].decode()
    return None


def check_refusal(out, err):
    """What breaks the contract of a refusal, or None."""
    if out:
        return "exit 2 with stdout: %r" % out[:200]
    if not err.endswith(b"\n") or err.count(b"\n") != 1:
        return "exit 2 without exactly one stderr line: %r" % err[:300]
    if not err.startswith(PROGRAM.encode() + b": "):
        return "message does not begin with the program's name: %r" % err[:200]
    if any(c < 32 or c > 126 for c in err[:-1]):
        return "message holds a control byte or a byte beyond ASCII: %r" % err[:300]
    return None


# the fuzz looks for hostile inputs, not long runs: unless an input sets
# max_collisions itself, it runs at most this many collisions; and the event
# table of a row longer than EVENTS_P_MOST (big output, written in full) is
# not asked for
RUN_CAP = b"max_collisions=3000"
EVENTS_P_MOST = 64


def keep_short(args):
    """The arguments with the caps above."""
    if not any(a.startswith(b"max_collisions=") for a in args):
        args = args + [RUN_CAP]
    long_row = any(a.startswith(b"p=") and a[2:].isdigit() and int(a[2:]) > EVENTS_P_MOST
                   for a in args)
    if long_row:
        args = [b"events=no" if a == b"events=yes" else a for a in args]
    return args


def run_case(binary, workdir, index, case, timeout):
    """Run one input; (outcome, breach or None, description)."""
    args = keep_short(list(case.args))
    stdin = subprocess.DEVNULL
    path = None
    if case.file_bytes is not None:
        path = os.path.join(workdir, "scene%d.nml" % index)
        with open(path, "wb") as f:
            f.write(case.file_bytes)
        if case.table:
            args = [b"spheres=" + path.encode()] + args
        elif case.stdin:
            args = [b"-"] + args
            stdin = open(path, "rb")
        else:
            args = [path.encode()] + args
    elif case.stdin:
        stdin = open("/dev/zero", "rb")
    described = "args=%r" % args + ("" if path is None else " file=%r%s" % (
        case.file_bytes[:400], " (on stdin)" if case.stdin else ""))
    try:
        done = subprocess.run([binary.encode()] + args, stdin=stdin, capture_output=True,
                              timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", "no answer within %g s (a hang)" % timeout, described
    except (OSError, ValueError) as failure:
        return "not run", "the fuzz could not start it: %s" % failure, described
    finally:
        if stdin not in (subprocess.DEVNULL, None):
            stdin.close()
        if path is not None:
            os.remove(path)
    if done.returncode < 0:
        return "signal", "killed by signal %d" % -done.returncode, described
    is_help = any(a in (b"--help", b"-h", b"help") for a in args)
    is_version = any(a == b"--version" for a in args)
    if done.returncode == 0:
        if is_help:
            breach = None if done.stdout.startswith(b"usage: ") and not done.stderr \
                else "help without usage"
            return "help", breach, described
        if is_version:
            breach = None if re.fullmatch(rb"sphere-row \d+\.\d+\.\d+\n", done.stdout) and \
                not done.stderr else "--version without one line 'sphere-row X.Y.Z'"
            return "help", breach, described
        events = any(a == b"events=yes" for a in args) or (
            case.file_bytes is not None and b"events" in case.file_bytes)
        printed = [a[len(b"print="):].decode() for a in args if a.startswith(b"print=")]
        printed = None if not printed or printed[-1] == "all" else printed[-1].split(",")
        return "answered", check_output(done.stdout, done.stderr, events, printed), described
    if done.returncode == 2:
        return "refused", check_refusal(done.stdout, done.stderr), described
    return "status", "exit status %d: %r" % (done.returncode, done.stderr[:300]), described


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--binary", required=True, help="the sphere-row executable")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--count", type=int, default=10000)
    parser.add_argument("--time-limit", type=float, default=60.0,
                        help="seconds the whole pass may take (0: no limit)")
    parser.add_argument("--timeout", type=float, default=10.0,
                        help="seconds one input may take before it counts as a hang")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    options = parser.parse_args()
    if not os.access(options.binary, os.X_OK):
        print("fuzz: --binary %s: not an executable" % options.binary, file=sys.stderr)
        return 2

    rng = random.Random(options.seed)
    cases = [make_case(rng, i) for i in range(options.count)]
    outcomes = {}
    breaches = []
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="sphere-row-fuzz-") as workdir:
        with concurrent.futures.ThreadPoolExecutor(max_workers=options.jobs) as pool:
            futures = [pool.submit(run_case, options.binary, workdir, i, c, options.timeout)
                       for i, c in enumerate(cases)]
            for i, future in enumerate(futures):
                outcome, breach, described = future.result()
                outcomes[outcome] = outcomes.get(outcome, 0) + 1
                if breach:
                    breaches.append((i, breach, described))
    seconds = time.monotonic() - start
    summary = ", ".join("%d %s" % (n, k) for k, n in sorted(outcomes.items()))
    print("fuzz: seed %d, %d inputs in %.1f s: %s" % (options.seed, options.count, seconds,
                                                        summary))
    for i, breach, described in breaches[:50]:
        print("fuzz: input %d: %s: %s" % (i, breach, described))
    if breaches:
        kinds = {}
        for _, breach, _ in breaches:
            kind = re.sub(r"[:(].*", "", breach).strip()
            kinds[kind] = kinds.get(kind, 0) + 1
        print("fuzz: %d inputs broke the contract: %s" % (len(breaches), "; ".join(
            "%d %s" % (n, k) for k, n in sorted(kinds.items(), key=lambda kn: -kn[1]))))
    over = options.time_limit > 0 and seconds > options.time_limit
    if over:
        print("fuzz: %.1f s is over the time limit of %g s" % (seconds, options.time_limit))
    return 1 if breaches or over else 0


if __name__ == "__main__":
    sys.exit(main())
