#!/usr/bin/env python3
"""Checks that the batch kernels compiled for AVX2/AVX-512 (src/batch/kernel_*.cpp) keep those
instruction sets to themselves.

Usage: check_isa_leaks.py OBJECT...

A kernel translation unit also emits out-of-line copies of inline functions it uses (std::, the scalar
query). Such a copy is a weak symbol: the linker keeps one copy per program, from any translation unit,
so a copy holding AVX instructions could be the one a plain x86-64 caller runs (SIGILL on a CPU without
them). src/batch/kernel_prelude.hpp prevents that by construction; this script proves it on the built
objects: every global or weak function that uses an instruction beyond plain x86-64 (VEX/EVEX, AVX-512
mask registers, BMI, LZCNT, POPCNT) must belong to a kernel's own namespace (dispatch_avx2,
dispatch_avx512), which only dispatch.cpp calls, after the CPU check. Local symbols (static functions,
compiler clones) cannot be picked by other translation units and are not checked. Exit status 1 and
the offending functions on a leak."""
import re
import subprocess
import sys

# Mnemonics beyond x86-64's baseline (SSE2): every VEX/EVEX instruction starts with "v"; AVX-512 mask
# instructions with "k"; and the BMI/ABM scalar ones. Not tzcnt: its encoding is REP BSF, which GCC
# emits for a count of trailing zeros in plain x86-64 code too (std::countr_zero, __builtin_ctz, with
# the zero input handled apart), since a CPU without BMI runs it as BSF; the disassembler names it
# tzcnt either way, so the mnemonic cannot tell a leak.
BEYOND = re.compile(r"^(v[a-z0-9]+|k[a-z]+|andn|bextr|blsi|blsmsk|blsr|bzhi|pdep|pext|rorx|sarx|shlx|shrx|mulx|lzcnt|popcnt)$")
OWN = ("dispatch_avx2", "dispatch_avx512")


def global_functions(obj):
    out = subprocess.run(["nm", "--defined-only", obj], check=True, capture_output=True, text=True).stdout
    names = set()
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] in "TWiu":  # global text, weak, indirect, unique
            names.add(parts[2])
    return names


def functions_beyond_baseline(obj):
    out = subprocess.run(["objdump", "-d", "--no-show-raw-insn", obj], check=True, capture_output=True,
                         text=True).stdout
    found, current = {}, None
    for line in out.splitlines():
        m = re.match(r"^[0-9a-f]+ <(.+)>:$", line)
        if m:
            current = m.group(1)
            continue
        fields = line.split("\t")
        if current and len(fields) >= 2:
            mnemonic = fields[1].split()[0] if fields[1].split() else ""
            if BEYOND.match(mnemonic) and current not in found:
                found[current] = mnemonic
    return found


def demangle(names):
    out = subprocess.run(["c++filt"], input="\n".join(names), check=True, capture_output=True, text=True).stdout
    return out.splitlines()


def main(objs):
    if not objs:
        print(__doc__)
        return 2
    leaks, checked = [], 0
    for obj in objs:
        globals_ = global_functions(obj)
        wide = functions_beyond_baseline(obj)
        exported = sorted(n for n in wide if n in globals_)
        checked += len(exported)
        for name, pretty in zip(exported, demangle(exported)):
            if not any(own in pretty for own in OWN):
                leaks.append(f"{obj}: {pretty}  (uses {wide[name]})")
        print(f"{obj}: {len(wide)} functions beyond x86-64, {len(exported)} of them global or weak, all in "
              f"{' / '.join(OWN)}" if not leaks else f"{obj}: checked")
    if leaks:
        print("Global or weak functions with AVX/BMI instructions outside the kernels' namespaces — a plain "
              "x86-64 caller could run them:")
        print("\n".join(leaks))
        return 1
    if checked == 0:
        print("no kernel functions found: wrong objects?")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
