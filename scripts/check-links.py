#!/usr/bin/env python3
"""Checks every relative link and #anchor in the repository's markdown files (GitHub-style
anchors: lowercase, spaces to -, punctuation other than - and _ removed).

    python3 scripts/check-links.py [ROOT]    # ROOT defaults to the repository root
"""
import re, os, sys, subprocess
root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
os.chdir(root)
files = subprocess.run(['git','ls-files','-co','--exclude-standard','*.md'],capture_output=True,text=True).stdout.split()
def slug(h):
    h = h.strip().lower()
    h = re.sub(r'[^\w\- ]', '', h)  # keep word chars, -, space
    return h.replace(' ', '-')
anchors = {}
def get_anchors(f):
    if f in anchors: return anchors[f]
    s=set(); counts={}
    infence=False
    for line in open(f, encoding='utf-8'):
        if line.startswith('```'): infence = not infence; continue
        if infence: continue
        m = re.match(r'^#{1,6}\s+(.*?)\s*#*\s*$', line)
        if m:
            a = slug(m.group(1))
            if a in counts: counts[a]+=1; a2=f"{a}-{counts[a]}"
            else: counts[a]=0; a2=a
            s.add(a2)
        for m in re.finditer(r'<a\s+(?:name|id)="([^"]+)"', line): s.add(m.group(1))
    anchors[f]=s; return s
bad=0; n=0
for f in files:
    text=open(f,encoding='utf-8').read()
    text=re.sub(r'```.*?```','',text,flags=re.S)
    text=re.sub(r'`[^`\n]*`','',text)
    for m in re.finditer(r'\]\(([^)\s]+)(?:\s+"[^"]*")?\)', text):
        url=m.group(1)
        if re.match(r'^[a-z]+:', url) : continue
        n+=1
        path, _, frag = url.partition('#')
        tgt = os.path.normpath(os.path.join(os.path.dirname(f), path)) if path else f
        if not os.path.exists(tgt):
            print(f"{f}: missing {url}"); bad+=1; continue
        if frag:
            if os.path.isdir(tgt) or not tgt.endswith('.md'):
                print(f"{f}: anchor on non-md {url}"); bad+=1; continue
            if frag not in get_anchors(tgt):
                print(f"{f}: bad anchor {url}"); bad+=1
print(f"{n} links checked, {bad} broken")
sys.exit(1 if bad else 0)
