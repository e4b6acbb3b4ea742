#!/usr/bin/env bash
# Prints the address of the Debian archive this machine's apt is configured with: the first
# `deb` source (deb822 .sources files or one-line .list files) that serves the suite given as
# $1 (default: this machine's codename) or, failing that, any suite of the `debian` archive.
# Used wherever a script needs an archive address (the deb-src entry of setup.sh, debootstrap),
# so that the project itself names no package host. Exits 1 with a message when none is found.
set -euo pipefail
suite="${1:-$(. /etc/os-release && echo "${VERSION_CODENAME:-}")}"
python3 - "$suite" <<'PY'
import glob, re, sys
suite = sys.argv[1]
entries = []  # (types, uris, suites, components)
def add(types, uris, suites, comps):
    entries.append((types, uris, suites, comps))
for path in sorted(glob.glob('/etc/apt/sources.list.d/*.sources')):
    try:
        text = open(path, encoding='utf-8', errors='replace').read()
    except OSError:
        continue
    for stanza in re.split(r'\n\s*\n', text):
        fields = {}
        key = None
        for line in stanza.splitlines():
            if line.startswith('#') or not line.strip():
                continue
            if line[0] in ' \t' and key:
                fields[key] += ' ' + line.strip()
                continue
            if ':' in line:
                key, _, value = line.partition(':')
                key = key.strip().lower()
                fields[key] = value.strip()
        if fields.get('enabled', 'yes').lower() == 'no':
            continue
        add(fields.get('types', '').split(), fields.get('uris', '').split(),
            fields.get('suites', '').split(), fields.get('components', '').split())
for path in ['/etc/apt/sources.list'] + sorted(glob.glob('/etc/apt/sources.list.d/*.list')):
    try:
        lines = open(path, encoding='utf-8', errors='replace').read().splitlines()
    except OSError:
        continue
    for line in lines:
        line = re.sub(r'\[[^\]]*\]', ' ', line.split('#', 1)[0]).split()
        if len(line) >= 3 and line[0] in ('deb', 'deb-src'):
            add([line[0]], [line[1]], [line[2]], line[3:])
def pick(pred):
    for types, uris, suites, comps in entries:
        if 'deb' in types and 'main' in comps and uris and pred(suites, uris[0]):
            return uris[0]
    return None
# The archive itself, not its -security or -updates pockets.
uri = pick(lambda s, u: suite in s and 'security' not in u)
uri = uri or pick(lambda s, u: any(x.split('-')[0] == suite for x in s) and 'security' not in u)
uri = uri or pick(lambda s, u: u.rstrip('/').endswith('/debian'))
if not uri:
    sys.exit(f"apt-archive: no deb source for suite '{suite}' (main) in this machine's apt sources")
print(uri.rstrip('/'))
PY
