#!/usr/bin/python3
"""Prints the apitrace call set of TRACE without the calls that only query the
window system or the implementation (extension strings, proc addresses,
framebuffer-config lists, piglit's framebuffer-bits queries): they change no
GL state, and in piglit traces they are most of the bytes.  Used with
`apitrace trim --calls=...`; call numbers are kept."""
import re
import subprocess
import sys

NOISE = re.compile(r'^(glGetStringi|glGetString|glXGetProcAddress(ARB)?|eglGetProcAddress|'
                   r'glGetFramebufferAttachmentParameteriv|glXGetFBConfigAttrib|'
                   r'glXQueryExtensionsString|glXGetClientString|glXQueryServerString|'
                   r'glXGetFBConfigs|glXChooseFBConfig|glGetIntegerv|glGetError)$')
out = subprocess.run(['apitrace', 'dump', '-v', '--color=never', sys.argv[1]], check=True,
                     stdout=subprocess.PIPE).stdout.decode('utf-8', 'replace')
keep = []
for line in out.splitlines():
    m = re.match(r'^(\d+) (?:@\d+ )?([A-Za-z_][A-Za-z0-9_]*)\(', line)
    if m and not NOISE.match(m.group(2)):
        keep.append(int(m.group(1)))
ranges, start, prev = [], None, None
for n in keep:
    if start is None:
        start = prev = n
    elif n == prev + 1:
        prev = n
    else:
        ranges.append((start, prev))
        start = prev = n
if start is not None:
    ranges.append((start, prev))
print(','.join('%d' % a if a == b else '%d-%d' % (a, b) for a, b in ranges))
