#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The laboratory's kept results, one compressed archive per experiment.

The many files of an experiment (a folder of shards, or a few large outputs) are kept in
laboratory/results/ as NAME.tar.xz. Each archive holds a MANIFEST (every file's size and path)
and the files, at the paths they have under laboratory/results/. laboratory/results/SHA256SUMS
holds each archive's SHA-256 (`sha256sum -c SHA256SUMS` in that folder checks them too), which
covers every byte of every file; xz adds its CRC64. (A SHA-256 per file would add 32
incompressible bytes a file: a fifth of the archives of many small files.) The archives are made the same way
byte for byte from the same files (sorted names, no dates, no owners), so packing unchanged
results changes nothing.

  results_archive.py list                          the archives and their files
  results_archive.py check                         every archive against SHA256SUMS and its MANIFEST
  results_archive.py unpack DEST [NAME ...]        unpacked into DEST (paths as under results/), checked
  results_archive.py pack NAME PATH [PATH ...]     the files and folders PATH (under results/) -> NAME.tar.xz

Scripts and tests find a folder of results with folder(NAME): under $EDGE_SWAP_LAB_UNPACKED
when it is set (where the tests unpack the archives), else in laboratory/results/ (where
`unpack laboratory/results` puts them).

Exit status 0 when everything checks, 1 when a file differs from its manifest, 2 for a bad
command line. Python's standard library only.
"""
import hashlib
import io
import lzma
import os
import sys
import tarfile

RESULTS = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "results"))
SUMS = os.path.join(RESULTS, "SHA256SUMS")
MANIFEST = "MANIFEST"


def folder(name):
    """Where the unpacked folder of results NAME is read and written."""
    return os.path.join(os.environ.get("EDGE_SWAP_LAB_UNPACKED") or RESULTS, name)


def sha256(data):
    return hashlib.sha256(data).hexdigest()


def archive_path(name):
    return os.path.join(RESULTS, name + ".tar.xz")


def archive_sums():
    """{name: sha256} from SHA256SUMS."""
    sums = {}
    if not os.path.exists(SUMS):
        return sums
    with open(SUMS, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            parts = line.split()
            if len(parts) != 2 or not parts[1].endswith(".tar.xz"):
                sys.exit("%s:%d: expected 'SHA256  NAME.tar.xz'" % (SUMS, number))
            sums[parts[1][: -len(".tar.xz")]] = parts[0]
    return sums


def write_sums(sums):
    with open(SUMS, "w", encoding="utf-8") as f:
        for name in sorted(sums):
            f.write("%s  %s.tar.xz\n" % (sums[name], name))


def members(name):
    """The archive's MANIFEST as {path: size} and its files as {path: bytes}."""
    files, listed = {}, None
    with tarfile.open(archive_path(name), "r:xz") as tar:
        for m in tar.getmembers():
            if not m.isfile():
                sys.exit("%s: %s is not a file" % (archive_path(name), m.name))
            data = tar.extractfile(m).read()
            if m.name == MANIFEST:
                listed = {}
                for line in data.decode("utf-8").splitlines():
                    size, path = line.split("  ", 1)
                    listed[path] = int(size)
            else:
                files[m.name] = data
    if listed is None:
        sys.exit("%s has no %s" % (archive_path(name), MANIFEST))
    return listed, files


def problems_of(name, sums):
    """The archive's differences from SHA256SUMS and its MANIFEST, as lines (none: it checks)."""
    with open(archive_path(name), "rb") as f:
        if sha256(f.read()) != sums[name]:
            return ["%s.tar.xz: its SHA-256 is not the one in SHA256SUMS" % name]
    listed, files = members(name)
    out = []
    for path in sorted(set(listed) | set(files)):
        if path not in files:
            out.append("%s: %s is listed but not in the archive" % (name, path))
        elif path not in listed:
            out.append("%s: %s is in the archive but not listed" % (name, path))
        elif len(files[path]) != listed[path]:
            out.append("%s: %s is not the size its manifest gives" % (name, path))
    return out


def pack(name, paths):
    """paths: files or folders under the results folder, kept at the same relative paths."""
    entries = []
    for path in paths:
        full = os.path.join(RESULTS, path)
        if os.path.isdir(full):
            for root, dirs, names in os.walk(full):
                dirs.sort()
                for n in sorted(names):
                    entries.append(os.path.relpath(os.path.join(root, n), RESULTS))
        else:
            entries.append(os.path.relpath(full, RESULTS))
    entries.sort()
    buffer = io.BytesIO()
    lines = []
    blobs = []
    for arcname in entries:
        with open(os.path.join(RESULTS, arcname), "rb") as f:
            data = f.read()
        blobs.append((arcname, data))
        lines.append("%d  %s" % (len(data), arcname))
    with tarfile.open(fileobj=buffer, mode="w", format=tarfile.PAX_FORMAT) as tar:
        for arcname, data in [(MANIFEST, ("\n".join(lines) + "\n").encode("utf-8"))] + blobs:
            info = tarfile.TarInfo(arcname)
            info.size, info.mtime, info.mode = len(data), 0, 0o644
            info.uid = info.gid = 0
            info.uname = info.gname = ""
            tar.addfile(info, io.BytesIO(data))
    compressed = lzma.compress(buffer.getvalue(), preset=9 | lzma.PRESET_EXTREME)
    with open(archive_path(name), "wb") as f:
        f.write(compressed)
    sums = archive_sums()
    sums[name] = sha256(compressed)
    write_sums(sums)
    print("%s.tar.xz: %d files, %d bytes" % (name, len(lines), len(compressed)))


def usage(message):
    print("results_archive.py: %s\n%s" % (message, __doc__), file=sys.stderr)
    return 2


def main(argv):
    if len(argv) < 2 or argv[1] not in ("list", "check", "unpack", "pack"):
        return usage("a command is missing or unknown")
    command, sums = argv[1], archive_sums()
    if command == "list":
        for name in sorted(sums):
            listed, _ = members(name)
            print("%-32s %5d files, %12d bytes unpacked" % (name, len(listed), sum(listed.values())))
        return 0
    if command == "check":
        problems = [p for name in sorted(sums) for p in problems_of(name, sums)]
        print("\n".join(problems) if problems else "%d archives check against SHA256SUMS and their manifests" % len(sums))
        return 1 if problems else 0
    if command == "pack":
        if len(argv) < 4:
            return usage("pack NAME PATH [PATH ...]")
        missing = [p for p in argv[3:] if not os.path.exists(os.path.join(RESULTS, p))]
        if missing:
            return usage("pack: %s is not under %s" % (", ".join(missing), RESULTS))
        pack(argv[2], argv[3:])
        return 0
    if len(argv) < 3:
        return usage("unpack DEST [NAME ...]: DEST is missing")
    wanted = argv[3:] or sorted(sums)
    unknown = [n for n in wanted if n not in sums]
    if unknown:
        return usage("unpack: no archive named %s (see 'list')" % ", ".join(unknown))
    for name in wanted:
        problems = problems_of(name, sums)
        if problems:
            print("\n".join(problems), file=sys.stderr)
            return 1
        for path, data in members(name)[1].items():
            out = os.path.join(argv[2], path)
            os.makedirs(os.path.dirname(out), exist_ok=True)
            with open(out, "wb") as f:
                f.write(data)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
