#!/usr/bin/env python3
"""Lists the commands printed in README.md and docs/**/*.md (fenced blocks and inline code naming shadowvol,
bash, python3, .sh, .py, ctest or cmake) as file:line, BLOCK|SPAN, text. Run from the repository root."""
import re,sys,glob,json
files=['README.md']+sorted(glob.glob('docs/**/*.md',recursive=True))
out=[]
for f in files:
    t=open(f).read()
    # fenced blocks
    lines=t.split('\n')
    inblock=False
    for i,l in enumerate(lines):
        if l.strip().startswith('```'):
            inblock=not inblock; continue
        if inblock and re.search(r'(shadowvol|bash |python3|\.sh\b|\.py\b)',l):
            out.append((f,i+1,'BLOCK',l.strip()))
    # inline spans (not fenced)
    t2=re.sub(r'```.*?```',lambda m:'\n'*m.group(0).count('\n'),t,flags=re.S)
    for m in re.finditer(r'`([^`]+)`',t2):
        s=m.group(1)
        if re.search(r'(shadowvol |bash |python3 |\.sh |\.py\b|ctest|cmake )',s):
            ln=t2.count('\n',0,m.start())+1
            out.append((f,ln,'SPAN',' '.join(s.split())))
for o in out: print(f"{o[0]}:{o[1]}\t{o[2]}\t{o[3]}")
