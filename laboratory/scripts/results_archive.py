#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The laboratory's kept results, one compressed archive per experiment.

Each folder of results (many shard files) is kept in laboratory/results/ as
NAME.tar.xz beside NAME.manifest, a text file that lists every file of the
archive with its size and SHA-256, and the SHA-256 of the archive itself. The
archives are made the same way byte for byte from the same files (sorted
names, no dates, no owners), so packing unchanged results changes nothing.

  results_archive.py list                       the archives and their files' counts
  results_archive.py check                      every archive against its manifest
  results_archive.py unpack DEST [NAME ...]     unpacked into DEST/NAME/, checked
  results_archive.py pack FOLDER                FOLDER/ -> FOLDER.tar.xz and .manifest

Scripts and tests find a folder of results with folder(NAME): under
$EDGE_SWAP_LAB_UNPACKED when it is set (where the tests unpack the archives),
else in laboratory/results/ (where `unpack laboratory/results` puts them).

Exit status 0 when everything checks, 1 when a file differs from its manifest,
2 for a bad command line. Python's standard library only.
"""
import hashlib
import io
import lzma
import os
import sys
import tarfile

RESULTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "results")


def folder(name):
    """Where the unpacked folder of results NAME is read and written."""
    return os.path.join(os.environ.get("EDGE_SWAP_LAB_UNPACKED") or RESULTS, name)


def sha256(data):
    return hashlib.sha256(data).hexdigest()


def manifest_path(name):
    return os.path.join(RESULTS, name + ".manifest")


def archive_path(name):
    return os.path.join(RESULTS, name + ".tar.xz")


def read_manifest(name):
    """The archive's checksum and {path: (size, sha256)}."""
    archive_sum, files = None, {}
    with open(manifest_path(name), encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                if line.startswith("# archive sha256 "):
                    archive_sum = line.split()[-1]
                continue
            parts = line.split("  ")
            if len(parts) != 3:
                sys.exit("%s:%d: expected 'SHA256  SIZE  PATH'" % (manifest_path(name), number))
            files[parts[2]] = (int(parts[1]), parts[0])
    return archive_sum, files


def names():
    return sorted(f[: -len(".manifest")] for f in os.listdir(RESULTS) if f.endswith(".manifest"))


def members(name):
    """{path: bytes} of the archive's regular files."""
    out = {}
    with tarfile.open(archive_path(name), "r:xz") as tar:
        for m in tar.getmembers():
            if m.isfile():
                out[m.name] = tar.extractfile(m).read()
            elif not m.isdir():
                sys.exit("%s: %s is neither a file nor a folder" % (archive_path(name), m.name))
    return out


def check_one(name):
    """The archive's differences from its manifest, as lines (none: it checks)."""
    archive_sum, listed = read_manifest(name)
    with open(archive_path(name), "rb") as f:
        data = f.read()
    if sha256(data) != archive_sum:
        return ["%s.tar.xz: its SHA-256 is not the manifest's" % name]
    found = members(name)
    problems = []
    for path in sorted(set(listed) | set(found)):
        if path not in found:
            problems.append("%s: %s is listed but not in the archive" % (name, path))
        elif path not in listed:
            problems.append("%s: %s is in the archive but not listed" % (name, path))
        elif (len(found[path]), sha256(found[path])) != listed[path]:
            problems.append("%s: %s differs from its manifest" % (name, path))
    return problems


def pack(folder):
    folder = os.path.normpath(folder)
    name = os.path.basename(folder)
    paths = []
    for root, dirs, files in os.walk(folder):
        dirs.sort()
        for f in sorted(files):
            full = os.path.join(root, f)
            paths.append((os.path.join(name, os.path.relpath(full, folder)), full))
    paths.sort()
    buffer = io.BytesIO()
    lines = []
    with tarfile.open(fileobj=buffer, mode="w", format=tarfile.PAX_FORMAT) as tar:
        for arcname, full in paths:
            with open(full, "rb") as f:
                data = f.read()
            info = tarfile.TarInfo(arcname)
            info.size, info.mtime, info.mode = len(data), 0, 0o644
            info.uid = info.gid = 0
            info.uname = info.gname = ""
            tar.addfile(info, io.BytesIO(data))
            lines.append("%s  %d  %s" % (sha256(data), len(data), arcname))
    compressed = lzma.compress(buffer.getvalue(), preset=9 | lzma.PRESET_EXTREME)
    with open(archive_path(name), "wb") as f:
        f.write(compressed)
    with open(manifest_path(name), "w", encoding="utf-8") as f:
        f.write("# %s.tar.xz: %d files, unpacked by laboratory/scripts/results_archive.py unpack DEST %s\n"
                % (name, len(lines), name))
        f.write("# archive sha256 %s\n" % sha256(compressed))
        f.write("# SHA256  SIZE  PATH\n")
        f.write("\n".join(lines) + "\n")
    print("%s.tar.xz: %d files, %d bytes" % (name, len(lines), len(compressed)))


def unpack(dest, wanted):
    for name in wanted:
        problems = check_one(name)
        if problems:
            print("\n".join(problems), file=sys.stderr)
            return 1
        for path, data in members(name).items():
            out = os.path.join(dest, path)
            os.makedirs(os.path.dirname(out), exist_ok=True)
            with open(out, "wb") as f:
                f.write(data)
    return 0


def main(argv):
    if len(argv) < 2 or argv[1] not in ("list", "check", "unpack", "pack"):
        print(__doc__, file=sys.stderr)
        return 2
    command = argv[1]
    if command == "list":
        for name in names():
            print("%-40s %5d files" % (name, len(read_manifest(name)[1])))
        return 0
    if command == "check":
        problems = [p for name in names() for p in check_one(name)]
        print("\n".join(problems) if problems else "%d archives check against their manifests" % len(names()))
        return 1 if problems else 0
    if command == "pack":
        if len(argv) != 3 or not os.path.isdir(argv[2]):
            print("pack FOLDER: FOLDER must be a folder of results", file=sys.stderr)
            return 2
        pack(argv[2])
        return 0
    if len(argv) < 3:
        print("unpack DEST [NAME ...]: DEST is missing", file=sys.stderr)
        return 2
    wanted = argv[3:] or names()
    unknown = [n for n in wanted if n not in names()]
    if unknown:
        print("unpack: no archive named %s (see 'list')" % ", ".join(unknown), file=sys.stderr)
        return 2
    return unpack(argv[2], wanted)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
