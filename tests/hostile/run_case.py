#!/usr/bin/env python3
"""Runs bounce-render on one case of tests/hostile/manifest.txt and checks it ended as
the manifest says: no signal, no sanitizer report, no hang, an allowed exit status, and
the required text in its messages.

  run_case.py --render build/bin/bounce-render --generated DIR NAME
  run_case.py --list                      # the case names (CMake registers one test each)
"""
import argparse
import os
import re
import resource
import shlex
import stat
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.join(HERE, "cases")
MANIFEST = os.path.join(HERE, "manifest.txt")
SKIPPED = 77  # ctest's SKIP_RETURN_CODE for these tests
# What the sanitizers print when they find something (they may not change the exit status
# when a program exits on its own, e.g. a leak found at exit with exitcode=0).
SANITIZER_REPORT = re.compile(r"ERROR: (AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer)|"
                              r"runtime error:|SUMMARY: (Address|Leak|UndefinedBehavior)Sanitizer")


def read_manifest():
    cases = {}
    with open(MANIFEST) as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            fields = [x.strip() for x in line.split("|")]
            if len(fields) != 4:
                sys.exit(f"{MANIFEST}:{number}: expected NAME | EXIT | MUST-SAY | ARGUMENTS")
            name, codes, must_say, args = fields
            if name in cases:
                sys.exit(f"{MANIFEST}:{number}: case {name} twice")
            cases[name] = ([int(c) for c in codes.split("/")], None if must_say == "-" else must_say,
                           shlex.split(args), number)
    return cases


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--render", help="bounce-render executable")
    parser.add_argument("--generated", help="folder of make_corpus.py --generated (made when missing)")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds before a run counts as a hang")
    parser.add_argument("name", nargs="?")
    a = parser.parse_args()
    cases = read_manifest()
    if a.list:
        print("\n".join(cases))
        return 0
    if not a.render or a.name not in cases:
        parser.error("need --render and a case name from the manifest")
    # The scratch folder (the case's outputs, FIFOs, device nodes, generated scenes when no
    # --generated folder is given) goes with the case: ctest runs hundreds of them.
    with tempfile.TemporaryDirectory(prefix=f"bounce-hostile-{a.name}-") as scratch:
        return run_case(a, cases[a.name], scratch)


def run_case(a, case, scratch):
    codes, must_say, args, number = case
    generated = os.path.abspath(a.generated or os.path.join(scratch, "generated"))
    wanted = [x.replace("@GEN@", generated) for x in args if "@GEN@" in x]
    if not all(os.path.exists(x) for x in wanted):
        # ctest runs cases in parallel: write into a private folder, then move it in place.
        tmp = tempfile.mkdtemp(prefix="generated-", dir=os.path.dirname(os.path.abspath(generated)))
        subprocess.run([sys.executable, os.path.join(HERE, "make_corpus.py"), "--generated", tmp], check=True)
        old = generated + ".old-" + os.path.basename(tmp)
        if os.path.exists(generated):
            os.rename(generated, old)  # an older generator's output
        try:
            os.rename(tmp, generated)
        except OSError:
            pass  # another case made it first
    # A case whose generated input is missing would pass as "bad input": the generator is broken.
    for x in args:
        path = x.replace("@GEN@", generated).split("=")[-1]
        if "@GEN@" in x and not os.path.exists(path):
            print(f"FAIL {a.name}: its input {path} does not exist ({MANIFEST}:{number})")
            return 1
    fifo = os.path.join(scratch, "fifo.ini")
    env = dict(os.environ)
    env.setdefault("BOUNCE_VALIDATION", "1")
    env["BOUNCE_USER_INI"] = os.path.join(scratch, "user.ini")  # never the machine's own
    env.setdefault("LSAN_OPTIONS", "suppressions=" + os.path.join(HERE, "..", "sanitizers", "lsan.supp"))
    env.setdefault("UBSAN_OPTIONS", "print_stacktrace=1:halt_on_error=1")
    # A case that reads without end (/dev/zero) must not take the machine's memory with it.
    # ASan reserves far more address space than it uses, so its builds get a 4 GiB RSS
    # limit; the others an 8 GiB address-space limit (lavapipe maps more than it touches).
    with open(a.render, "rb") as f:
        asan = b"__asan_init" in f.read()
    env.setdefault("ASAN_OPTIONS", "hard_rss_limit_mb=4096")
    limit = 8 << 30
    limit_memory = None if asan else (lambda: resource.setrlimit(resource.RLIMIT_AS, (limit, limit)))
    argv = [os.path.abspath(a.render)]
    for x in args:
        x = x.replace("@CASES@", CASES).replace("@GEN@", generated).replace("@SCRATCH@", scratch)
        if "@FIFO@" in x or "@FIFOLINK@" in x:
            if not os.path.exists(fifo):
                os.mkfifo(fifo)
            x = x.replace("@FIFO@", fifo)
        if "@FIFOLINK@" in x:
            link = os.path.join(scratch, "link-to-fifo.png")
            if not os.path.lexists(link):
                os.symlink(fifo, link)
            x = x.replace("@FIFOLINK@", link)
        if "@CHARDEV@" in x:
            # A character device like /dev/null (1, 3), made in the scratch folder: no test
            # ever names a real /dev path. Making one needs root (CAP_MKNOD).
            device = os.path.join(scratch, "null-device")
            if not os.path.exists(device):
                try:
                    os.mknod(device, 0o666 | stat.S_IFCHR, os.makedev(1, 3))
                except PermissionError:
                    print(f"skipped {a.name}: making a device node needs root")
                    return SKIPPED
            x = x.replace("@CHARDEV@", device)
        if x.startswith("env:"):
            key, _, value = x[4:].partition("=")
            env[key] = value
        else:
            argv.append(x)
    if "--width" not in argv:
        argv += ["--width", "16", "--height", "16"]
    if "--gi" not in argv:
        argv += ["--gi", "none"]

    print(f"{MANIFEST}:{number}: {a.name}")
    print("  $ " + " ".join(shlex.quote(x) for x in argv))
    try:
        run = subprocess.run(argv, env=env, cwd=scratch, stdin=subprocess.DEVNULL, capture_output=True,
                             timeout=a.timeout, preexec_fn=limit_memory)
    except subprocess.TimeoutExpired as e:
        print((e.stderr or b"").decode(errors="replace")[-4000:])
        print(f"FAIL {a.name}: still running after {a.timeout:.0f} s (a hang)")
        return 1
    out = run.stdout.decode(errors="replace")
    err = run.stderr.decode(errors="replace")
    print(out[-2000:] + err[-8000:])
    problems = []
    if run.returncode < 0:
        problems.append(f"killed by signal {-run.returncode}")
    if SANITIZER_REPORT.search(err):
        problems.append("a sanitizer report")
    if run.returncode not in codes:
        problems.append(f"exit status {run.returncode}, expected {'/'.join(map(str, codes))}")
    if must_say and must_say not in err:
        problems.append(f"no message containing '{must_say}'")
    if "\x1b" in err:
        problems.append("a raw ESC byte in its messages (control bytes must be escaped)")
    if problems:
        print(f"FAIL {a.name}: " + "; ".join(problems))
        return 1
    print(f"ok {a.name}: exit {run.returncode}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
