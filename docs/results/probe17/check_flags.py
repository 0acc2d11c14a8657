#!/usr/bin/env python3
"""Static pass of the seventeenth probe: every `shadowvol <subcommand> ...` printed in README.md,
docs/**/*.md, scripts/* and docs/results/**/*.{sh,py}, its --long-options checked against
`EXE <subcommand> --help` and its bench --methods against `EXE bench --list-methods`.
Prints file:line, subcommand, unknown options/methods (a few false positives: commands cut short).
Usage (from the repository root): python3 docs/results/probe17/check_flags.py [build/apps/shadowvol]"""
import glob, re, subprocess, sys
exe = sys.argv[1] if len(sys.argv) > 1 else "build/apps/shadowvol"
subs = "scene depth build check render validate bench".split()
help = {c: set(re.findall(r"--[a-z][a-z0-9-]*", subprocess.run([exe, c, "--help"], capture_output=True, text=True).stdout)) | {"--help"} for c in subs}
methods = {l.split()[0] for l in subprocess.run([exe, "bench", "--list-methods"], capture_output=True, text=True).stdout.splitlines() if l.strip()}
STOP_MD = r"(`|\n\s*\n|\n```|&&|\|\||;|\|(?!\w)|\bshadowvol\b)"
STOP_SH = r"(&&|\|\||;|\|(?!\w)|\bshadowvol\b|\n)"
files = ["README.md"] + sorted(glob.glob("docs/**/*.md", recursive=True)) + sorted(glob.glob("scripts/*")) + \
        sorted(glob.glob("docs/results/**/*.sh", recursive=True)) + sorted(glob.glob("docs/results/**/*.py", recursive=True))
pat = re.compile(r'(?:shadowvol|\$SV|"\$SV"|\$exe|"\$exe"|\$V|"\$V"|\bsv\b|\{sv\}|BIN)["\']?(?:\s+(?:-q|-v|--quiet|--verbose))?\s*["\']?,?\s*["\']?(scene|depth|build|check|render|validate|bench)\b')
for f in files:
    t = open(f, errors="replace").read().replace("\\\n", " ")
    for m in pat.finditer(t):
        sub, rest = m.group(1), t[m.end():m.end() + 1500]
        stop = re.search(STOP_MD if f.endswith(".md") else STOP_SH, rest)
        seg = rest[:stop.start()] if stop else rest
        bad = [x for x in re.findall(r"(?<![\w-])--[a-z][a-z0-9-]*", seg) if x not in help[sub]]
        badm = []
        mm = re.search(r"--methods[ =]+(.*?)(?=\s--|$)", seg, re.S)
        if mm:
            badm = [x for x in re.split(r"[ ,\"'\n]+", mm.group(1)) if re.match(r"^[a-z][a-z0-9/-]+$", x) and x not in methods]
        if bad or badm:
            print(f"{f}:{t.count(chr(10), 0, m.start()) + 1}\t{sub}\tunknown options {bad}\tunknown methods {badm}")
