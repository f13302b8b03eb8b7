#!/usr/bin/env python3
"""The bad-input campaign: every option of every lesson given values a user might
type by mistake (or on purpose), --out pointed at what is not a folder, and hostile
scene and OBJ files. Each run must end as the project promises: one line on stderr
that starts with "<lesson>: error: " and status 2 for what is refused; and what is
accepted must get as far as the output folder (every run is given an --out that
cannot be made, /proc/gi_campaign, so an accepted command line stops there, before
any work). Never a crash, a hang, a traceback, a NaN, a second line, or a quote from
a file that is not the user's scene.

Usage: campaign.py BIN_DIR WORK_DIR [--quick] [--emulator COMMAND...]
(every program but the Tachyon and Embree benches, or with --quick lessons 01, 08, 11, 14;
a cross build's programs run through its emulator, as ctest runs them: qemu-aarch64,
wine). Prints one line per failure and a summary; exit status 1 if anything failed,
or if no lesson was found to run.
"""
import os
import re
import subprocess
import sys
from pathlib import Path

SENTINEL = "/proc/gi_campaign"
SECRET = "gi-campaign-secret-line"  # the first line of files no message may quote

# Values a real or whole-number option is given, and whether each is a number at all.
NOT_NUMBERS = ["nan", "inf", "-inf", "abc", "", "0x10", "1e", " 5", "5 ", "+5", "1e400", "-1e400",
               "\u0661", "\u0663\u0662", "\uff15", "1,5", "5\x1b[2J", "--", "-", ".", "e5", "1e+", "0x1p4",
               "99999999999999999999", "-99999999999999999999", "1" * 400]
SUBNORMAL = ["-1e-320", "4.9e-324"]


EMULATOR = []  # the words that run a cross build's program (--emulator), or none


def program(bin_dir, lesson):
    """The argv that runs a lesson: its file (lesson.exe for Windows) through the emulator."""
    path = Path(bin_dir) / lesson
    exe = path.with_name(lesson + ".exe")
    return EMULATOR + [str(exe if exe.is_file() and not path.is_file() else path)]


def options_of(binary):
    """(name, kind, range) from --help: kind is int, real, seed, choice, text, parsed or flag."""
    text = subprocess.run(binary + ["--help"], capture_output=True, text=True, timeout=30).stdout
    found = []
    for line in text.splitlines():
        m = re.match(r"^  (--[a-z0-9-]+)( VALUE)?\s+(.*)$", line)
        # --help and --options-json print and exit before any other option is read,
        # once or twice: not options of the run to be attacked.
        if not m or m.group(1) in ("--help", "--options-json"):
            continue
        name, takes, rest = m.group(1), m.group(2), m.group(3)
        r = re.search(r"range \[([^,]+), ([^\]]+)\]", rest)
        if not takes:
            found.append((name, "flag", None))
        elif "written" in rest:
            found.append((name, "parsed", None))
        elif "one of:" in rest:
            found.append((name, "choice", None))
        elif r:
            lo, hi = r.group(1), r.group(2)
            kind = "real" if any(c in lo + hi for c in ".e") else "int"
            found.append((name, kind, (float(lo), float(hi))))
        elif "2^64" in rest:
            found.append((name, "seed", None))
        else:
            found.append((name, "text", None))
    return found


class Campaign:
    def __init__(self, bin_dir, work):
        self.bin, self.work = Path(bin_dir).resolve(), Path(work).resolve()
        self.runs = self.refused = self.accepted = 0
        self.failures = []

    def run(self, lesson, args, expect, why, env=None):
        """expect: "refuse" (status 2, one line, not the sentinel), "accept" (the
        sentinel's line), "either" (one of the two), or "fail" (status 1 or 2, one line)."""
        self.runs += 1
        try:
            p = subprocess.run(program(self.bin, lesson) + args, capture_output=True, timeout=60, env=env, cwd=self.work)
        except subprocess.TimeoutExpired:
            self.fail(f"{lesson} {args!r}: still running after 60 s ({why})")
            return
        err = p.stderr.decode("utf-8", "replace")
        out = p.stdout.decode("utf-8", "replace")
        # Warnings (a scene without lights) may come first: one line each, and not the error.
        lines = [l for l in err.splitlines() if not l.startswith(lesson + ": warning: ")]
        problem = None
        if p.returncode < 0:
            problem = f"killed by signal {-p.returncode}"
        elif SECRET in err or SECRET in out:
            problem = "quoted a file that is not the user's"
        elif re.search(r"(^|[^A-Za-z])(nan|inf)([^A-Za-z]|$)", out):
            problem = "printed nan or inf"
        elif re.search("[\x00-\x08\x0b-\x1f\x7f\u202a-\u202e\u2066-\u2069]", err):
            problem = "a control character on stderr (it can rewrite the terminal)"
        elif "Traceback" in err or "terminate called" in err or "runtime error:" in err:
            problem = "crashed"
        elif p.returncode == 0:
            problem = "exit status 0"
        elif len(lines) != 1 or not lines[0].startswith(lesson + ": error: "):
            problem = f"{len(lines)} lines on stderr"
        else:
            reached = SENTINEL in lines[0]
            if expect == "refuse" and (reached or p.returncode != 2):
                problem = "accepted" if reached else f"status {p.returncode}"
            elif expect == "accept" and not reached:
                problem = "refused"
            elif expect == "either" and p.returncode != 2:
                problem = f"status {p.returncode}"
            else:
                self.accepted += reached
                self.refused += not reached
        if problem:
            self.fail(f"{lesson} {args!r}: {problem} ({why}):\n    {err.strip()[:300]!r}")

    def fail(self, text):
        self.failures.append(text)
        print(text, flush=True)

    # -- options ---------------------------------------------------------------------
    def numeric(self, lesson, name, kind, rng):
        for v in NOT_NUMBERS:
            self.run(lesson, [name, v, "--out", SENTINEL], "refuse", "not a number")
        lo, hi = rng if rng else (0.0, 2.0 ** 64 - 1)
        for v in SUBNORMAL:
            self.run(lesson, [name, v, "--out", SENTINEL], "refuse", "subnormal or not whole")
        # -0 is 0; 1e308 is a real number; the ends of the range and just past them.
        zero_ok = kind != "seed" and lo <= 0 <= hi
        self.run(lesson, [name, "-0", "--out", SENTINEL], "accept" if zero_ok else "refuse", "-0")
        self.run(lesson, [name, "1e308", "--out", SENTINEL],
                 "accept" if kind == "real" and hi >= 1e308 else "refuse", "1e308")
        if kind in ("int", "real"):
            for v, ok in ((lo, True), (hi, True)):
                text = str(int(v)) if kind == "int" else repr(v)
                self.run(lesson, [name, text, "--out", SENTINEL], "either", f"an end of [{lo}, {hi}]")
            past = (str(int(lo) - 1), str(int(hi) + 1)) if kind == "int" else (repr(lo - abs(lo) - 1), repr(hi * 2 + 1))
            for text in past:
                self.run(lesson, [name, text, "--out", SENTINEL], "refuse", "past the range")
        if kind == "seed":
            for v in ("0", "18446744073709551615"):
                self.run(lesson, [name, v, "--out", SENTINEL], "accept", "an end of the seeds")
            self.run(lesson, [name, "18446744073709551616", "--out", SENTINEL], "refuse", "past 2^64 - 1")
            self.run(lesson, [name, "-1", "--out", SENTINEL], "refuse", "negative seed")

    def parsed(self, lesson, name):
        if name == "--camera":
            for v in NOT_NUMBERS + SUBNORMAL:
                self.run(lesson, [name, v + ",0,0:0,0,1", "--out", SENTINEL], "refuse", "camera coordinate")
                self.run(lesson, [name, "0,0,0:0,0,1:" + v, "--out", SENTINEL], "refuse", "camera field of view")
            for v in ("0,0,0:0,0,0", "1e7,0,0:0,0,0", "0,0,0:0,0,1:180", "0,0,0:0,0,1:0", "0,0,0", "::", "a:b:c:d"):
                self.run(lesson, [name, v, "--out", SENTINEL], "refuse", "camera")
            self.run(lesson, [name, "-0,0,5:0,0,0:40", "--out", SENTINEL], "accept", "camera with -0")
        elif name == "--light-scale":
            for v in NOT_NUMBERS + SUBNORMAL + ["-1", "1e7"]:
                self.run(lesson, [name, "light=" + v, "--out", SENTINEL], "refuse", "light factor")
            for v in ("light", "=2", "nosuchlight=2", "light=1,light=2", "light=0", "light=-0", "\x1b[2J=1", ","):
                self.run(lesson, [name, v, "--out", SENTINEL], "refuse", "light scale")
            for v in ("light=1e-300", "light=1e6"):
                self.run(lesson, [name, v, "--out", SENTINEL], "accept", "light factor at an end")
        else:
            self.run(lesson, [name, "", "--out", SENTINEL], "refuse", "empty")

    def options(self, lesson):
        opts = options_of(program(self.bin, lesson))
        for name, kind, rng in opts:
            if kind in ("int", "real", "seed"):
                self.numeric(lesson, name, kind, rng)
            elif kind == "choice":
                for v in ["", "x", "\x1b[2J", "BVH ", "1"]:
                    self.run(lesson, [name, v, "--out", SENTINEL], "refuse", "not a choice")
            elif kind == "flag":
                self.run(lesson, [name + "=1", "--out", SENTINEL], "refuse", "a flag with a value")
                self.run(lesson, [name, name, "--out", SENTINEL], "refuse", "a flag twice")
            elif kind == "parsed":
                self.parsed(lesson, name)
            if kind != "flag":
                self.run(lesson, [name], "refuse", "no value")
                self.run(lesson, [name, "--out"], "refuse", "an option for a value")
            # Given twice.
            if kind in ("int", "real"):
                lo, hi = rng
                v = str(int(lo)) if kind == "int" else repr(lo)
                self.run(lesson, [name, v, name, v, "--out", SENTINEL], "refuse", "given twice")
        self.run(lesson, ["--bogus", "--out", SENTINEL], "refuse", "unknown option")
        self.run(lesson, ["\x1b[2J", "--out", SENTINEL], "refuse", "an argument that is no option")

    # -- --out -------------------------------------------------------------------------
    def outs(self, lesson):
        plain = self.work / "a_file"
        plain.write_text("keep me\n")
        readonly = self.work / "read_only"
        readonly.mkdir(exist_ok=True)
        readonly.chmod(0o500)
        targets = [str(plain), str(plain / "x"), "/proc", "/proc/self", "/dev/full", "/dev/null", "/dev/full/x", "",
                   "-x", "--", "x" * 5000, "/" + "x" * 300]
        if os.geteuid() != 0:
            targets.append(str(readonly / "x"))
        for target in targets:
            self.run(lesson, ["--out", target], "fail", f"--out {target[:40]}")
        if plain.read_text() != "keep me\n":
            self.fail(f"{lesson}: --out changed the file it was pointed at")

    # -- scene and OBJ files -----------------------------------------------------------
    def scenes(self, lessons):
        d = self.work / "scenes"
        (d / "room").mkdir(parents=True, exist_ok=True)
        secret = self.work / "secret.obj"
        secret.write_text(SECRET + "\n")
        (d / "room" / "notes.txt").write_text(SECRET + "\n")
        (d / "room" / "secret_in.obj").write_text(SECRET + "\n")
        link = d / "room" / "link.obj"
        if not link.exists():
            link.symlink_to(secret)
        camera = '"camera": {"eye": [0, 1, 5], "look_at": [0, 1, 0]}'
        matte = '"materials": [{"name": "white", "diffuse": 0.7, "emission": 1}]'

        def scene(name, rest, text=None):
            path = d / "room" / name
            path.write_bytes((text if text is not None else "{" + camera + ", " + matte + rest + "}").encode("utf-8", "surrogateescape"))
            return str(path)

        def mesh(name, file):
            return scene(name, ', "meshes": [{"file": "' + file + '", "material": "white"}]')

        cases = [
            mesh("up.json", "../../secret.obj"),
            mesh("absolute.json", str(secret)),
            mesh("shadow.json", "/etc/shadow"),
            mesh("link.json", "link.obj"),
            mesh("txt.json", "notes.txt"),
            mesh("not_obj_text.json", "secret_in.obj"),
            mesh("dev.json", "/dev/zero"),
            mesh("folder.json", "."),
            mesh("nothing.json", "nothing.obj"),
            scene("nan.json", "", "{" + camera + ', "spheres": [{"center": [NaN, 0, 0], "radius": 1, "material": "w"}]}'),
            scene("hex.json", "", "{" + camera + ', "spheres": [{"center": [0x10, 0, 0], "radius": 1}]}'),
            scene("plus.json", "", "{" + camera + ', "spheres": [{"center": [+1, 0, 0], "radius": 1}]}'),
            scene("subnormal.json", ', "spheres": [{"center": [1e-320, 0, 0], "radius": 1, "material": "white"}]'),
            scene("huge.json", ', "spheres": [{"center": [1e308, 0, 0], "radius": 1, "material": "white"}]'),
            scene("deep.json", "", "[" * 100000),
            scene("escape.json", ', "spheres": [{"center": [0, 0, 0], "radius": 1, "material": "\\u001b[2J"}]'),
            scene("bidi.json", ', "spheres": [{"center": [0, 0, 0], "radius": 1, "material": "\u202ewhite"}]'),
            scene("control.json", "", "{" + camera + ', "name": "a\x07b"}'),
            scene("bom_only.json", "", "\ufeff"),
            scene("empty.json", "", ""),
            scene("cut.json", "", "{" + camera[:30]),
            scene("latin1.json", "", '{"name": "\udce9t\udce9"}'),
            scene("tiny.json", ', "quads": [{"corner": [0, 0, 0], "edge_u": [1e-300, 0, 0], "edge_v": [0, 1e-300, 0], "material": "white"}]'),
            str(d / "room"),  # a folder
            str(d / "room" / "missing.json"),
        ]
        # An OBJ of 10^6 faces: every lesson refuses it at its own limit, quickly.
        big = d / "room" / "big.obj"
        if not big.exists():
            big.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl white\n" + "f 1 2 3\n" * 1_000_000)
        cases.append(mesh("big.json", "big.obj"))
        objs = {"obj_hex.obj": "v 0x10 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                "obj_nan.obj": "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                "obj_index.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n",
                "obj_zero.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
                "obj_control.obj": "v 0 0 0\x1b[2J\n",
                "obj_long.obj": "v " + "1" * 100000 + " 0 0\n",
                "obj_empty.obj": ""}
        for name, text in objs.items():
            (d / "room" / name).write_text(text)
            cases.append(mesh(name.replace(".obj", ".json"), name))
        for lesson in lessons:
            for case in cases:
                self.run(lesson, ["--scene", case, "--out", SENTINEL], "either", f"scene {Path(case).name}")


def main():
    argv = sys.argv[1:]
    if "--emulator" in argv:
        EMULATOR[:] = argv[argv.index("--emulator") + 1:]
        argv = argv[:argv.index("--emulator")]
    bin_dir, work = argv[0], Path(argv[1])
    quick = "--quick" in argv
    work.mkdir(parents=True, exist_ok=True)
    c = Campaign(bin_dir, work)
    lessons = sorted(p.name.removesuffix(".exe") for p in Path(bin_dir).iterdir()
                     if re.match(r"^\d\d_", p.name) and p.is_file() and (os.access(p, os.X_OK) or p.suffix == ".exe"))
    if quick:
        lessons = [l for l in lessons if l in ("01_rays", "08_radiosity_system", "11_progressive", "14_path_tracing")]
    # The benches beside lessons 02 and 05 (Tachyon, Embree) are measurements, not
    # lessons: they check --out when they write, after minutes of work.
    lessons = [l for l in lessons if l not in ("02_tachyon_bench", "05_embree_bench")]
    for lesson in lessons:
        c.options(lesson)
        c.outs(lesson)
    if not lessons:
        print(f"bad-input campaign: no lesson found in {bin_dir}: nothing was checked")
        return 1
    scene_lessons = [l for l in lessons if "--scene" in [o[0] for o in options_of(program(bin_dir, l))]
                     and l not in ("14_path_tracing", "14_make_reference", "16_two_pass")]
    c.scenes(scene_lessons)
    print(f"bad-input campaign: {c.runs} runs over {len(lessons)} programs; {c.refused} refused in one line, "
          f"{c.accepted} accepted up to the output folder; {len(c.failures)} wrong")
    return 1 if c.failures else 0


if __name__ == "__main__":
    sys.exit(main())
