"""before_main: what a graded program runs before main, read from the program itself.

The harness reads the signing key first of all, from the program's one entry of
.preinit_array (support/graded_main.cpp), before any constructor. A region cannot put
code there (the text check refuses attributes and asm), and this check makes sure of it
after the build, from the ELF file: .preinit_array holds exactly one entry, the
harness's key reader (after AddressSanitizer's set-up in a sanitized build), and every
entry of .init_array is a compiler-made initialiser of a file's globals
(_GLOBAL__sub_I_...) or one of the toolchain's runtimes' (RUNTIME): a function a
submission placed there by any other means is named and the program refused.

    before_main.py PROGRAM...     prints one line per program; exit status 1 if any is refused

Programs that are not ELF (Windows, macOS) are not checked: there the signed report
rests on the text check alone (exercises/README.md says so).
"""
import struct
import sys
from pathlib import Path

KEY_READER = "_ZN12_GLOBAL__N_18read_keyEiPPcS1_"  # (anonymous namespace)::read_key(int, char**, char**)
INITIALISER = "_GLOBAL__sub_I_"
# What the toolchain's own runtimes put there: the C runtime's frame_dummy; libgcc's
# CPU feature probe (x86-64) and its choice of atomics (AArch64); AddressSanitizer's
# set-up, which must precede everything, and its registration of each file's globals.
RUNTIME = {"frame_dummy", "__cpu_indicator_init", "init_have_lse_atomics", "asan.module_ctor"}
RUNTIME_FIRST = {"__asan_init", "__lsan_init", "__ubsan_init_standalone_preinit"}  # the sanitizers' own set-up
# Relocation types that fill a slot with the load address plus the addend (PIE).
RELATIVE = {62: 8, 183: 1027}  # e_machine (x86-64, AArch64): R_*_RELATIVE


class ElfError(Exception):
    pass


class Elf:
    """The sections, symbols and dynamic relocations of a 64-bit little-endian ELF file."""

    def __init__(self, data):
        if data[:4] != b"\x7fELF":
            raise ElfError("not an ELF file")
        if data[4] != 2 or data[5] != 1:
            raise ElfError("not a 64-bit little-endian ELF file")
        self.data = data
        self.machine = struct.unpack_from("<H", data, 18)[0]
        shoff, = struct.unpack_from("<Q", data, 40)
        shentsize, shnum, shstrndx = struct.unpack_from("<HHH", data, 58)
        headers = [struct.unpack_from("<IIQQQQIIQQ", data, shoff + k * shentsize) for k in range(shnum)]
        names = headers[shstrndx]
        self.sections = {}
        for h in headers:
            name = self.string(names[4], h[0])
            self.sections[name] = {"type": h[1], "addr": h[3], "offset": h[4], "size": h[5], "link": h[6],
                                   "entsize": h[9]}
        self.headers = headers

    def string(self, table_offset, at):
        end = self.data.index(b"\0", table_offset + at)
        return self.data[table_offset + at:end].decode("utf-8", errors="replace")

    def functions(self):
        """{address: name} of the symbol table's functions and objects."""
        symtab = self.sections.get(".symtab")
        if symtab is None:
            raise ElfError("it has no symbol table (stripped)")
        strtab = self.headers[symtab["link"]][4]
        found = {}
        for k in range(symtab["size"] // 24):
            name, info, _, _, value, _ = struct.unpack_from("<IBBHQQ", self.data, symtab["offset"] + 24 * k)
            if value and info & 0xF in (1, 2):  # STT_OBJECT, STT_FUNC
                found.setdefault(value, self.string(strtab, name))
        return found

    def relative_targets(self):
        """{slot address: target address} of the dynamic relocations that fill a slot with
        the load address plus an addend."""
        kind = RELATIVE.get(self.machine)
        targets = {}
        for section in self.sections.values():
            if section["type"] != 4 or kind is None:  # SHT_RELA
                continue
            for k in range(section["size"] // 24):
                offset, info, addend = struct.unpack_from("<QQq", self.data, section["offset"] + 24 * k)
                if info & 0xFFFFFFFF == kind:
                    targets[offset] = addend
        return targets

    def array(self, name):
        """The addresses an array of function pointers holds ([] when it is absent)."""
        section = self.sections.get(name)
        if section is None:
            return []
        relocated = self.relative_targets()
        slots = []
        for k in range(section["size"] // 8):
            at = section["addr"] + 8 * k
            stored, = struct.unpack_from("<Q", self.data, section["offset"] + 8 * k) if section["type"] != 8 else (0,)
            slots.append(relocated.get(at, stored))
        return slots


def refusal(program):
    """Why the program must not run ("" when what runs before main is the harness's and
    the compiler's alone, or when it is not ELF)."""
    try:
        data = Path(program).read_bytes()
    except OSError as e:
        return f"cannot be read ({e.strerror})"
    try:
        elf = Elf(data)
    except ElfError:
        return ""  # not ELF: not this check's system
    except (struct.error, ValueError, IndexError):
        return "is not a well-formed ELF file"
    try:
        names = elf.functions()
        preinit, init = elf.array(".preinit_array"), elf.array(".init_array")
    except ElfError as e:
        return f"cannot be checked: {e}"
    except (struct.error, ValueError, IndexError):
        return "is not a well-formed ELF file"
    named = lambda address: names.get(address, f"the code at {address:#x}")  # noqa: E731
    first = [named(a) for a in preinit if named(a) not in RUNTIME_FIRST]
    if first != [KEY_READER] or [named(a) for a in preinit][-1] != KEY_READER:
        others = [named(a) for a in preinit if named(a) != KEY_READER]
        return ("runs code before the harness reads its key: .preinit_array holds " +
                (", ".join(others) if others else "no key reader"))
    strangers = [named(a) for a in init if not (named(a).startswith(INITIALISER) or named(a) in RUNTIME)]
    if strangers:
        return f"runs code before main that no file's globals need: .init_array holds {', '.join(strangers)}"
    return ""


def main(argv):
    if len(argv) < 2:
        print("usage: before_main.py PROGRAM...", file=sys.stderr)
        return 2
    refused = 0
    for program in argv[1:]:
        why = refusal(program)
        print(f"{program}: {'refused: ' + why if why else 'only the harness and the compiler run before main'}")
        refused += bool(why)
    return 1 if refused else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
