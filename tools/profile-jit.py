#!/usr/bin/env python3
"""Where a running program's lavapipe shaders spend their time, instruction block by block.

lavapipe compiles shaders to x86 with LLVM at run time and registers no symbols for
them, so `perf report` shows only "[JIT]". This samples the program with perf while it
runs, copies its anonymous executable mappings (the JIT code) out with gdb before it
exits, disassembles them and attributes the samples:

  - per mapping (a shader module, or a group of small ones): its share of all samples;
  - in the busiest mappings, per straight-line block (code up to a jump, call or return):
    instructions, share of the samples, and memory loads. lavapipe's texture samplers are
    separate functions called from the shader (`call *%reg`); an RGBA16F trilinear sample
    of 8 lanes is one block of 64 eight-byte loads (`vmovsd (…)`).

Samples per instruction compare the blocks' speed. Blocks of different instruction mixes
run at different rates anyway; the same block compared across runs (a larger data set, a
smaller texel format) shows what memory costs it.

  tools/profile-jit.py [--delay S] [--seconds S] [--top N] -- COMMAND [ARGS...]
  tools/profile-jit.py -- build/bin/bounce-render-bench --gi VXGI --sizes 128 --frames 400 \\
      --variant "s128: r.VXGI.MapSize=128"

The command must still run after --delay + --seconds (give it enough frames); it is
stopped afterwards. Needs perf (linux-perf), gdb and objdump (binutils); ptrace and
perf_event permissions as root has them. A measuring tool, not part of the build.
"""
import argparse
import collections
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

GDB_DUMP = r'''
import gdb, os
inferior = gdb.selected_inferior()
out = os.environ["PROFILE_JIT_DIR"]
with open("/proc/%d/maps" % inferior.pid) as maps:
    for line in maps:
        fields = line.split()
        # Anonymous (no path) executable mappings: the JIT's code.
        if "x" in fields[1] and len(fields) < 6:
            begin, end = (int(x, 16) for x in fields[0].split("-"))
            data = inferior.read_memory(begin, end - begin)
            with open(os.path.join(out, "%x.bin" % begin), "wb") as f:
                f.write(bytes(data))
'''

LINE = re.compile(r"\s*([0-9a-f]+):\s+(?:[0-9a-f]{2} )+\s*(.*)")


def fail(message):
    print(f"profile-jit: {message}", file=sys.stderr)
    sys.exit(2)


def disassemble(path, base):
    out = subprocess.run(["objdump", "-D", "-b", "binary", "-mi386:x86-64", f"--adjust-vma={base:#x}", path],
                         capture_output=True, text=True, check=True).stdout
    code = []
    for line in out.splitlines():
        m = LINE.match(line)
        if m and m.group(2).strip():
            code.append((int(m.group(1), 16), m.group(2).strip()))
    return code


def is_load(instruction):
    operands = instruction.partition(" ")[2]
    # A memory source operand: "(" before the last comma (AT&T puts the destination last).
    return "(" in operands.rsplit(",", 1)[0] if "," in operands else False


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--delay", type=float, default=8.0, help="seconds before sampling starts (set-up, ceilings)")
    parser.add_argument("--seconds", type=float, default=6.0, help="seconds sampled")
    parser.add_argument("--top", type=int, default=2, help="mappings shown block by block")
    parser.add_argument("--min-share", type=float, default=0.5, help="blocks under this %% of a mapping's samples are left out")
    parser.add_argument("--show-blocks", type=float, default=101.0,
                        help="print the instructions (and samples) of blocks holding at least this %% of a mapping's samples")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command:
        fail("no command given (tools/profile-jit.py [options] -- COMMAND ...)")
    for tool, package in (("perf", "linux-perf"), ("gdb", "gdb"), ("objdump", "binutils")):
        if not shutil.which(tool):
            fail(f"{tool} not found (Debian package {package})")

    work = tempfile.mkdtemp(prefix="profile-jit.")
    try:
        report(args, command, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def report(args, command, work):
    program = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        time.sleep(args.delay)
        if program.poll() is not None:
            fail(f"the command exited (status {program.returncode}) before sampling started; give it more work")
        samples = os.path.join(work, "perf.data")
        subprocess.run(["perf", "record", "-q", "-F", "4000", "-o", samples, "-p", str(program.pid), "--", "sleep",
                        str(args.seconds)], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if program.poll() is not None:
            fail("the command exited while it was sampled: its JIT code is gone; give it more work")
        dumps = os.path.join(work, "jit")
        os.mkdir(dumps)
        subprocess.run(["gdb", "-q", "-batch", "-p", str(program.pid), "-ex", "python\n" + GDB_DUMP + "\nend"],
                       env=dict(os.environ, PROFILE_JIT_DIR=dumps), check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
    finally:
        if program.poll() is None:
            program.send_signal(signal.SIGTERM)
            try:
                program.wait(timeout=10)
            except subprocess.TimeoutExpired:
                program.kill()

    ips = subprocess.run(["perf", "script", "-i", samples, "-F", "ip"], capture_output=True, text=True).stdout
    hits = collections.Counter(int(line.split()[0], 16) for line in ips.splitlines() if line.strip())
    total = sum(hits.values())
    if total == 0:
        fail("perf recorded no samples")
    mappings = []
    for name in os.listdir(dumps):
        base = int(name[:-4], 16)
        size = os.path.getsize(os.path.join(dumps, name))
        mappings.append((sum(n for ip, n in hits.items() if base <= ip < base + size), base, size, name))
    mappings.sort(reverse=True)
    jit = sum(m[0] for m in mappings)
    print(f"{total} samples; {100 * jit / total:.1f}% in lavapipe's JIT code ({len(mappings)} mappings)\n")
    print("| mapping | KiB | samples |")
    print("|---|---:|---:|")
    for count, base, size, _ in mappings:
        if count > 0.005 * total:
            print(f"| {base:#x} | {size // 1024} | {100 * count / total:.1f}% |")

    for count, base, size, name in mappings[: args.top]:
        if count == 0:
            continue
        code = disassemble(os.path.join(dumps, name), base)
        print(f"\nmapping {base:#x}: {100 * count / total:.1f}% of all samples; its blocks "
              f"(≥ {args.min_share}% of its samples):\n")
        print("| first instruction | instructions | loads | samples | samples per instruction | ends with |")
        print("|---:|---:|---:|---:|---:|---|")
        start = 0
        shown = []
        for i, (address, instruction) in enumerate(code):
            if instruction.startswith(("j", "call", "ret")) or i == len(code) - 1:
                block = code[start : i + 1]
                n = sum(hits.get(a, 0) for a, _ in block)
                if n >= args.min_share / 100 * count:
                    loads = sum(1 for _, x in block if is_load(x))
                    print(f"| {block[0][0] - base:#x} | {len(block)} | {loads} | {100 * n / count:.1f}% | "
                          f"{n / len(block):.2f} | `{instruction.split()[0]}` |")
                    if n >= args.show_blocks / 100 * count:
                        shown.append((block, n))
                start = i + 1
        for block, n in shown:
            print(f"\nblock {block[0][0] - base:#x} ({100 * n / count:.1f}% of the mapping's samples):")
            for address, instruction in block:
                print(f"  {address - base:#8x} {hits.get(address, 0):6d}  {instruction}")


if __name__ == "__main__":
    main()
