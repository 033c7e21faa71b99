"""Where the ``elastica`` command writes: output paths per input, and the one
writer of files (:class:`Outputs`): an output that is an input is refused, every
output goes to a temporary first and is renamed into place only when all of them
were written (issue 12: the command never damages its input, and a failing output
leaves nothing behind)."""
from __future__ import annotations

import os
import re
import shutil
import stat
import sys
import tempfile
from pathlib import Path
from typing import List, Optional, Sequence

from .io import InputError

class ToStdout(str):
    """An output option given as '-': standard output. Equal to "-"; knows the option
    (for messages) and the format's suffix (the writers choose the format by it)."""

    def __new__(cls, option: str, ext: str):
        obj = super().__new__(cls, "-")
        obj.option, obj.ext = option, ext
        return obj


def out_path(spec: Optional[str], source: str, ext: str, batch: bool):
    """Output path for one input: spec itself, spec with {stem} filled in, or (batch,
    no {stem}) a directory spec/ holding <stem><ext>; '-' (standard output) as it is.
    Nothing is created here: :class:`Outputs` makes the output's own directory (one
    level) when the file is written."""
    if not spec:
        return None
    if spec == "-":
        return spec
    stem = "stdin" if source == "-" else Path(source).stem
    if "{stem}" in spec:
        return Path(spec.replace("{stem}", stem))
    if batch:
        return Path(spec) / f"{stem}{ext}"
    return Path(spec)


def _mode_for(final: Path) -> int:
    """The permissions of an output: the file's own when it is replaced, else those the
    umask gives a new file (0644 under umask 022), not mkstemp's 0600 for its temporary."""
    try:
        return stat.S_IMODE(os.stat(final).st_mode)
    except OSError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


def _names_a_descriptor(path) -> bool:
    """Whether ``path`` names an open file descriptor through /proc/self/fd (Linux's
    /dev/stdout, /dev/stderr, /dev/fd/N, bash's >(...)): its links followed one at a time,
    one of them lies in a process's fd directory."""
    p = os.path.abspath(path)
    for _ in range(40):                 # (the kernel's ELOOP limit)
        if re.fullmatch(r"/proc/(self|\d+)/fd", os.path.realpath(os.path.dirname(p))):
            return True
        if not os.path.islink(p):
            return False
        p = os.path.join(os.path.dirname(p), os.readlink(p))
    return False


def output_key(final) -> object:
    """One key for every name of one file, so two outputs to it are caught whatever names
    them: an existing regular file by its inode (hard links too), any other path with its
    links resolved (os.path.realpath: two links to one file, or to one new file, passed the
    same-output check when the key was the path as written). An open descriptor
    (/dev/stdout, /dev/fd/N) keeps the path as written: it is written through at its end, as
    the shell opened it, so two of them on one file or device (`--json /dev/stdout --dxf
    /dev/stderr > log 2>&1`, or `> /dev/null 2>&1`) are two outputs one after the other."""
    if _names_a_descriptor(final):
        return os.path.abspath(final)
    try:
        node = os.stat(final)
        if stat.S_ISREG(node.st_mode):
            return (node.st_dev, node.st_ino)
    except OSError:
        pass
    return os.path.realpath(final)


def _release_fifo(path) -> None:
    """Open a FIFO output for writing without blocking and close it: its reader, if one
    waits, sees the end of the file, as it would after a shell's '> fifo' of a command that
    failed (an output never written left the reader blocked for ever). Without a reader the
    open fails (ENXIO) and nothing happens."""
    try:
        os.close(os.open(path, os.O_WRONLY | os.O_NONBLOCK))
    except OSError:
        pass


class Outputs:
    """The one place the command writes files (every subcommand goes through it).

    - An output that is one of the command's inputs (the same file: by os.path.samefile,
      so ``./a.csv``, links and ``{stem}`` patterns are caught) is refused before
      anything is written (InputError: exit 2); so is a path given twice.
    - Each output is written to a temporary next to it (same suffix, so the writers
      still choose the format by it); :meth:`commit` renames them all into place
      only when every one was written, :meth:`abort` removes them (and the
      directories made for them): a failing output leaves nothing behind.
    - '-' (:class:`ToStdout`) is standard output: written to a temporary in a directory of
      its own and copied to stdout at commit (nothing on stdout when the command fails).
    - An output that is a link replaces the file the link names (the link stays); one that
      is not a regular file (a FIFO, /dev/null, a terminal, a pipe named /dev/stdout or
      /dev/fd/N) is written through at commit, as a shell's redirection writes it: renaming onto it replaced the device node itself
      (QA23: as root ``--json /dev/full`` turned /dev/full into a JSON file, exit 0).

    A subcommand names its input files ``file`` / ``files`` (or sets ``args.inputs``)
    and writes with ``path = args.outputs.path(target)`` then ``write_x(..., path)``.
    """

    def __init__(self, inputs: Sequence[str]):
        self._inputs = [Path(p) for p in inputs if p and p != "-" and Path(p).exists()]
        self._staged: List[tuple] = []      # (temporary, final, where): where is the file
        # renamed onto (final, or the file a link names), None for '-' and written-through ones
        self._finals: set = set()
        self._made: List[Path] = []         # directories created, deepest last
        self._private_dir: Optional[str] = None    # temporaries of '-' and written-through ones
        self._fifos: dict = {}              # output_key -> FIFO named as an output

    def check(self, target) -> Path:
        """Refuse target when it is an input or already an output of this command."""
        if target == "-":
            return target
        final = Path(target)
        if final.is_dir():
            raise InputError(f"{final}: is a directory; give a file name")
        if final.exists():
            for inp in self._inputs:
                try:
                    same = os.path.samefile(final, inp)
                except OSError:
                    same = False
                if same:
                    raise InputError(f"{final}: refusing to overwrite the input file {inp}")
        key = output_key(final)
        if key in self._finals:
            raise InputError(f"{final}: the same output path is given twice")
        self.note_fifo(final)
        return final

    def note_fifo(self, final) -> None:
        """Remember ``final`` if it is a FIFO: released at abort (or commit, unwritten)."""
        try:
            if stat.S_ISFIFO(os.stat(final).st_mode):
                self._fifos[output_key(final)] = final
        except OSError:
            pass

    def path(self, target) -> Path:
        """A temporary to write ``target``'s content to (renamed at commit; '-': copied to
        standard output)."""
        if target == "-":
            return self._private(target, getattr(target, 'ext', '.tmp'))
        final = self.check(target)
        self._finals.add(output_key(final))
        where = Path(os.path.realpath(final)) if final.is_symlink() else final
        try:
            node = os.stat(final)   # follows links, /proc/self/fd's to pipes too
        except OSError:
            node = None
        # not a regular file, or an open descriptor (/dev/stdout, /dev/fd/N: a pipe's link
        # names pipe:[inode], no path to rename onto; a file's is the one the shell opened,
        # '>>' appending: renaming onto it dropped its earlier lines)
        if node is not None and (not stat.S_ISREG(node.st_mode) or not where.exists() or
                                 _names_a_descriptor(final)):
            return self._private(final, final.suffix or ".tmp")
        # the output's own directory is made when its parent exists (out/{stem}.json, a
        # batch's --svg pics: one level, as mkdir makes it); a path missing more is a typo
        # (QA21 F7: --json /nonexistent/dir/x.json made /nonexistent/dir at the root, exit
        # 0): refused, nothing made or written, as cp, tar and curl refuse it
        parent = where.parent
        if not parent.exists():
            if not parent.parent.exists():
                top = parent.parent
                while not top.parent.exists():
                    top = top.parent
                raise InputError(f"{final}: no directory {top} (it makes only the output's "
                                 f"own directory, {parent.name}, in one that exists)")
            try:
                parent.mkdir()
            except OSError as exc:
                raise InputError(f"{final}: cannot make its directory "
                                 f"({exc.strerror})") from None
            self._made.append(parent)
        try:
            fd, tmp = tempfile.mkstemp(prefix=f".{where.name}.", suffix=where.suffix or ".tmp",
                                       dir=str(where.parent))
        except OSError as exc:
            raise InputError(f"{final}: cannot write there ({exc.strerror})") from None
        os.close(fd)
        self._staged.append((Path(tmp), final, where))
        return Path(tmp)

    def _private(self, final, suffix: str) -> Path:
        """A temporary in the command's own directory, for an output copied at commit
        (standard output, a FIFO or device)."""
        if self._private_dir is None:
            self._private_dir = tempfile.mkdtemp(prefix="elastica-out.")
        tmp = Path(self._private_dir) / f"{len(self._staged)}{suffix}"
        tmp.touch()
        self._staged.append((tmp, final, None))
        return tmp

    def mark(self) -> int:
        """A point to :meth:`rollback` to (a batch drops the outputs of a failed file)."""
        return len(self._staged)

    def rollback(self, mark: int) -> None:
        for tmp, final, _ in self._staged[mark:]:
            self._finals.discard(output_key(final))
            try:
                tmp.unlink()
            except OSError:
                pass
        del self._staged[mark:]

    def commit(self) -> None:
        # written-through outputs first: they can fail (/dev/full), and then no file is
        # renamed into place and nothing goes to stdout
        for tmp, final, where in self._staged:
            if where is None and final != "-":
                self._fifos.pop(output_key(final), None)
                try:
                    # a descriptor's file at its end, where this command's other writes to
                    # it went ('>' or '>>'); a FIFO or device as it is
                    mode = "ab" if _names_a_descriptor(final) else "wb"
                    sys.stdout.flush()      # what it printed first, before this at its end
                    with open(tmp, "rb") as src, open(final, mode) as dst:
                        shutil.copyfileobj(src, dst)
                except OSError as exc:
                    raise InputError(f"{final}: cannot write ({exc.strerror})") from None
        for tmp, final, where in self._staged:
            if final == "-":
                sys.stdout.flush()
                with open(tmp, "rb") as src:
                    shutil.copyfileobj(src, sys.stdout.buffer)
                sys.stdout.buffer.flush()
            elif where is not None:
                os.chmod(tmp, _mode_for(where))
                os.replace(tmp, where)
        self._staged = []
        self._drop_private_dir()
        self._release_fifos()       # a FIFO whose output a batch's failed file dropped

    def _release_fifos(self) -> None:
        for fifo in self._fifos.values():
            _release_fifo(fifo)
        self._fifos = {}

    def explain(self, message: str) -> str:
        """message with each temporary's name replaced by what the user gave (the file,
        or '--OPTION -'): an error names no temporary."""
        for tmp, final, _ in self._staged:
            name = f"--{final.option} -" if final == "-" and hasattr(final, "option") else str(final)
            message = message.replace(str(tmp), name)
        return message

    def _drop_private_dir(self) -> None:
        if self._private_dir is not None:
            shutil.rmtree(self._private_dir, ignore_errors=True)
            self._private_dir = None

    def abort(self) -> None:
        for tmp, _, _ in self._staged:
            try:
                tmp.unlink()
            except OSError:
                pass
        self._drop_private_dir()
        for d in reversed(self._made):
            try:
                d.rmdir()
            except OSError:
                pass
        self._staged, self._made = [], []
        self._release_fifos()


OUTPUT_OPTIONS = (("json", ".json"), ("svg", ".svg"), ("png", ".png"), ("dxf", ".dxf"))


def check_outputs(args) -> None:
    """Fail early (before any work) on outputs this installation cannot write, and on
    an output that would replace an input (the same check again at writing)."""
    files = list(getattr(args, "files", None) or [])
    batch = len(files) > 1
    taken = {}          # output path -> the option that writes it
    to_stdout = []
    # every FIFO named, before any output is refused: a FIFO after the refused one was never
    # checked, so never released (`--json a.csv --dxf p`: the input refused, p's reader
    # blocked for ever, where `--json p --dxf a.csv` released it)
    for opt, ext in OUTPUT_OPTIONS:
        spec = getattr(args, opt, None)
        if spec and spec != "-":
            for source in files or [spec]:
                args.outputs.note_fifo(out_path(spec, source, ext, batch))
    for opt, ext in OUTPUT_OPTIONS:
        spec = getattr(args, opt, None)
        if spec == "-":
            # '-' is standard output for every format (--dxf - wrote a file named '-',
            # --svg - failed naming a temporary: QA17)
            if batch and opt != "json":
                raise InputError(f"--{opt} -: {len(files)} input files make {len(files)} "
                                 f"{opt.upper()}s; give a file name (or '{{stem}}.{ext[1:]}')")
            if opt == "png" and sys.stdout.isatty():
                raise InputError("--png -: standard output is a terminal; redirect it "
                                 "(> picture.png) or give a file name")
            to_stdout.append(opt)
            if len(to_stdout) > 1:
                raise InputError(f"--{to_stdout[0]} - and --{opt} -: one output can go to "
                                 "standard output; give the other a file name")
            setattr(args, opt, ToStdout(opt, ext))
            continue
        if not spec:
            continue
        for source in files or [spec]:
            final = args.outputs.check(out_path(spec, source, ext, batch))
            # two outputs to one path: the later one replaced the earlier without a word
            # (--json o.json --dxf o.json exited 0 with a DXF there)
            key = output_key(final)
            if key in taken and taken[key] != opt:
                raise InputError(f"--{opt} {final}: the same output path is given twice (also "
                                 f"--{taken[key]}): give each output its own file")
            taken[key] = opt
            # a picture's format is its name's (the writers choose by it): --svg x.png
            # wrote a PNG without a word
            if opt in ("svg", "png") and final.suffix.lower() != ext:
                raise InputError(f"--{opt} {final}: the picture's file name must end in {ext}")
    args.to_stdout = bool(to_stdout)
    # the DXF's units without a DXF: silently nothing
    if getattr(args, "units", None) is not None and not getattr(args, "dxf", None):
        raise InputError(f"--units {args.units} sets the DXF's units: give --dxf too")
    if getattr(args, "png", None):
        from .report import have_matplotlib
        if not have_matplotlib():
            raise InputError("--png needs matplotlib (pip install matplotlib); --svg works without it")
    if getattr(args, "dxf", None):
        from .io import have_ezdxf
        if not have_ezdxf():
            raise InputError("--dxf needs the optional package ezdxf (pip install ezdxf)")
