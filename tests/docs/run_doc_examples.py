#!/usr/bin/python3
"""Runs the fenced examples of README.md and docs/*.md (not docs/records) as written.

Each ```c, ```cmake, ```python and ```sh block is checked; the HTML comment on the line
before a block (blank lines between are allowed) says how, when the block alone cannot be
compiled or run:

  (none)                          c: a complete program (it has main): compiled with
                                  -std=c99 -pedantic -Wall -Wextra -Werror, linked with
                                  libgrass and run. python: run as is, with
                                  integration/python on PYTHONPATH and GRASS_LIBRARY set.
                                  sh: bash -n, and every repository path it names exists
                                  (build/DIR/NAME: DIR's CMakeLists.txt makes NAME).
  <!-- doc-test: prelude=NAME -->  wrapped in tests/docs/preludes/NAME.c (or .py) at its
                                  "doc-test block" line, then as above.
  <!-- doc-test: fragment of PATH -->
                                  every line of the block (comments and blanks aside) is
                                  a line of PATH, in order; PATH is built and run by its
                                  own test. A readme-example marker ("generated from PATH")
                                  counts as one.
  <!-- doc-test: cmake-project files=SRC:DEST,... run=EXE -->
                                  the block is a CMakeLists.txt: configured against the
                                  build's installed tree (CMAKE_PREFIX_PATH), built with
                                  the files copied in, and EXE run.
  <!-- doc-test: skip: REASON -->  not run, listed in the output. Only for what cannot run
                                  here.
  <!-- doc-test: install-run files=SRC:DEST,... -->
                                  sh: an install command, run exactly as written by
                                  --install-run (ctest docs_install_commands): the marked
                                  blocks of one document, in order, in one bash -e session
                                  whose working folder is a copy of the repository's tracked
                                  files (FILES copied in beside them), inside a user and mount
                                  namespace with an empty tmpfs over /opt, so a command that
                                  installs under /opt runs as written and leaves the machine
                                  untouched. Without --install-run such a block gets the sh
                                  checks above.

A c, cmake or python block without a marker that is not complete fails the test, so a new
example cannot slip through untested. Other languages (json, cpp, qml, text) are counted
but not run.

    run_doc_examples.py --build BUILD_DIR [--scratch DIR] [--cc CC] [--python PYTHON]
    run_doc_examples.py --install-run [--scratch DIR]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PRELUDES = os.path.join(ROOT, "tests", "docs", "preludes")
RUN = {"c", "cmake", "python", "sh"}
MARK = re.compile(r"^<!--\s*doc-test:\s*(.*?)\s*-->$")
GENERATED = re.compile(r"^<!--\s*readme-example:begin: generated from (\S+)")
REPO_PATH = re.compile(r"(?<![\w/.$-])((?:scripts|samples|tools|test_hosts|docs|integration|tests|api|backend_gl|backend_vk|build)"
                       r"/[\w./+-]*[\w+-])")


class Block:
    def __init__(self, path, line, lang, text, mark):
        self.path, self.line, self.lang, self.text, self.mark = path, line, lang, text, mark

    def where(self):
        return f"{os.path.relpath(self.path, ROOT)}:{self.line}"


def doc_files():
    files = [os.path.join(ROOT, "README.md")]
    docs = os.path.join(ROOT, "docs")
    files += [os.path.join(docs, n) for n in sorted(os.listdir(docs)) if n.endswith(".md")]
    return files


def blocks(path):
    lines = open(path, encoding="utf-8").read().split("\n")
    out, i, last = [], 0, None
    while i < len(lines):
        line = lines[i]
        m = re.match(r"^```(\S*)\s*$", line)
        if m:
            lang, start = m.group(1), i + 1
            i += 1
            while i < len(lines) and not lines[i].startswith("```"):
                i += 1
            mark = None
            if last is not None:
                mm, gm = MARK.match(last), GENERATED.match(last)
                if mm:
                    mark = mm.group(1)
                elif gm:
                    mark = "fragment of " + gm.group(1)
            out.append(Block(path, start, lang, "\n".join(lines[start:i]) + "\n", mark))
            last = None
        elif line.strip():
            last = line.strip()
        i += 1
    return out


def code_lines(text):
    """The lines of C or Python code, without comments, blanks and trailing spaces."""
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    out = []
    for line in text.split("\n"):
        line = re.sub(r"\s//.*$|^//.*$", "", line).strip()
        if line:
            out.append(re.sub(r"\s+", " ", line))
    return out


class Runner:
    def __init__(self, args):
        self.args = args
        self.build = os.path.abspath(args.build)
        self.scratch = os.path.abspath(args.scratch or os.path.join(self.build, "docs-test"))
        shutil.rmtree(self.scratch, ignore_errors=True)
        os.makedirs(self.scratch)
        self.library = os.path.join(self.build, "libgrass.so")
        self.prefix = None
        self.count = 0

    def scratch_dir(self, block):
        self.count += 1
        d = os.path.join(self.scratch, f"{self.count:02d}-{os.path.basename(block.path)[:-3]}-{block.line}")
        os.makedirs(d)
        return d

    def run(self, cmd, cwd, env=None, timeout=120):
        r = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           timeout=timeout)
        if r.returncode != 0:
            raise RuntimeError(f"{' '.join(cmd)} exited {r.returncode}:\n{r.stdout[-4000:]}")
        return r.stdout

    def wrap(self, block, prelude_name, ext):
        prelude = os.path.join(PRELUDES, prelude_name + ext)
        if not os.path.isfile(prelude):
            raise RuntimeError(f"no prelude {os.path.relpath(prelude, ROOT)}")
        text = open(prelude, encoding="utf-8").read()
        anchor = re.search(r"^([ \t]*)(/\* doc-test block \*/|# doc-test block)$", text, flags=re.M)
        if not anchor:
            raise RuntimeError(f"{prelude_name}{ext} has no 'doc-test block' line")
        indent = anchor.group(1)
        body = "".join(indent + line + "\n" if line else "\n" for line in block.text.rstrip("\n").split("\n"))
        flags = re.search(r"doc-test flags: (.*?) \*/", text)
        return text[:anchor.start()] + body + text[anchor.end() + 1:], flags.group(1).split() if flags else []

    def c(self, block, prelude):
        source, flags = (block.text, []) if prelude is None else self.wrap(block, prelude, ".c")
        if prelude is None and not re.search(r"\bint\s+main\s*\(", source):
            raise RuntimeError("a C fragment without a marker: give it a prelude, a 'fragment of' source or a "
                               "skip reason (tests/docs/run_doc_examples.py)")
        d = self.scratch_dir(block)
        with open(os.path.join(d, "block.c"), "w", encoding="utf-8") as f:
            f.write(source)
        self.run([self.args.cc, "-std=c99", "-pedantic", "-Wall", "-Wextra", "-Werror", "-Wno-unused-variable",
                  "-Wno-unused-but-set-variable", "-Wno-unused-function", "-I" + os.path.join(ROOT, "api", "include"),
                  "block.c", "-o", "block", self.library, "-Wl,-rpath," + self.build, "-lm"] + flags, d)
        return self.run(["./block"], d)

    def python(self, block, prelude):
        source = block.text if prelude is None else self.wrap(block, prelude, ".py")[0]
        d = self.scratch_dir(block)
        with open(os.path.join(d, "block.py"), "w", encoding="utf-8") as f:
            f.write(source)
        env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "integration", "python"), GRASS_LIBRARY=self.library)
        return self.run([self.args.python, "block.py"], d, env=env)

    def install(self):
        if self.prefix is None:
            self.prefix = os.path.join(self.scratch, "prefix")
            self.run(["cmake", "--install", self.build, "--prefix", self.prefix], self.scratch)
        return self.prefix

    def cmake_project(self, block, options):
        opts = dict(o.split("=", 1) for o in options.split() if "=" in o)
        d = self.scratch_dir(block)
        with open(os.path.join(d, "CMakeLists.txt"), "w", encoding="utf-8") as f:
            f.write(block.text)
        for pair in filter(None, opts.get("files", "").split(",")):
            src, _, dest = pair.partition(":")
            shutil.copy(os.path.join(ROOT, src), os.path.join(d, dest or os.path.basename(src)))
        env = dict(os.environ)
        env.pop("LD_LIBRARY_PATH", None)  # the documented run path must be enough
        self.run(["cmake", "-S", ".", "-B", "b", "-DCMAKE_PREFIX_PATH=" + self.install()], d, env=env)
        self.run(["cmake", "--build", "b"], d, env=env)
        return self.run([os.path.join("b", opts["run"])], d, env=env) if "run" in opts else ""

    def fragment(self, block, source):
        path = os.path.join(ROOT, source)
        if not os.path.isfile(path):
            raise RuntimeError(f"fragment of {source}: no such file")
        have = code_lines(open(path, encoding="utf-8").read())
        at = 0
        for line in code_lines(block.text):
            try:
                at = have.index(line, at) + 1
            except ValueError:
                raise RuntimeError(f"fragment of {source}: this line is not in it (after its line {at}): {line}")
        return f"its lines are {source}'s"

    def sh(self, block):
        r = subprocess.run(["bash", "-n"], input=block.text, text=True, stderr=subprocess.PIPE)
        if r.returncode != 0:
            raise RuntimeError("bash -n: " + r.stderr)
        text = re.sub(r"#[^\n]*", "", block.text)
        for path in REPO_PATH.findall(text):
            if path.startswith("build/"):
                parts = path.split("/")
                lists = os.path.join(ROOT, *parts[1:-1], "CMakeLists.txt")
                if len(parts) > 2 and os.path.isfile(lists):
                    if not re.search(r"\b" + re.escape(parts[-1]) + r"\b", open(lists, encoding="utf-8").read()):
                        raise RuntimeError(f"{path}: {os.path.relpath(lists, ROOT)} makes no {parts[-1]}")
                elif len(parts) > 2 and not parts[-1].startswith("grass-demo"):
                    raise RuntimeError(f"{path}: no {'/'.join(parts[1:-1])}/CMakeLists.txt makes it")
            elif not os.path.exists(os.path.join(ROOT, path)):
                raise RuntimeError(f"{path} does not exist")
        return "bash -n and its paths"

    def check(self, block):
        mark = block.mark or ""
        if mark.startswith("skip:"):
            return "skip", mark[5:].strip()
        if mark.startswith("fragment of "):
            return "ok", self.fragment(block, mark[len("fragment of "):].strip())
        prelude = None
        m = re.match(r"prelude=(\S+)$", mark)
        if m:
            prelude = m.group(1)
        elif mark.startswith("cmake-project"):
            if block.lang != "cmake":
                raise RuntimeError("cmake-project marks a cmake block")
            return "ok", self.cmake_project(block, mark[len("cmake-project"):])
        elif mark.startswith("install-run"):
            if block.lang != "sh":
                raise RuntimeError("install-run marks an sh block")
            return "ok", self.sh(block)
        elif mark:
            raise RuntimeError(f"unknown doc-test marker: {mark}")
        if block.lang == "c":
            return "ok", self.c(block, prelude)
        if block.lang == "python":
            return "ok", self.python(block, prelude)
        if block.lang == "sh":
            return "ok", self.sh(block)
        raise RuntimeError("a cmake block needs a cmake-project marker (or a skip reason)")


def tracked_copy(dest):
    """A copy of the repository's tracked files (what a fresh clone holds) under dest."""
    names = subprocess.run(["git", "-C", ROOT, "ls-files", "-z"], stdout=subprocess.PIPE, check=True).stdout
    for name in filter(None, names.decode().split("\0")):
        src = os.path.join(ROOT, name)
        if os.path.isfile(src):
            os.makedirs(os.path.join(dest, os.path.dirname(name)), exist_ok=True)
            shutil.copy2(src, os.path.join(dest, name))


def install_run(scratch):
    """Runs the install-run blocks of each document as written (see the module's text)."""
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    ran = 0
    for path in doc_files():
        marked = [b for b in blocks(path) if (b.mark or "").startswith("install-run")]
        if not marked:
            continue
        src = os.path.join(scratch, os.path.basename(path)[:-3])
        tracked_copy(src)
        for block in marked:
            opts = dict(o.split("=", 1) for o in block.mark.split()[1:] if "=" in o)
            for pair in filter(None, opts.get("files", "").split(",")):
                file_src, _, file_dest = pair.partition(":")
                shutil.copy(os.path.join(ROOT, file_src), os.path.join(src, file_dest or os.path.basename(file_src)))
        script = "mount -t tmpfs grass-doc-test /opt\ncd \"$1\"\nset -e -x\n" + "".join(
            f"# {b.where()}\n{b.text}" for b in marked)
        env = {k: v for k, v in os.environ.items() if k not in ("LD_LIBRARY_PATH", "PKG_CONFIG_PATH", "CMAKE_PREFIX_PATH")}
        r = subprocess.run(["unshare", "--map-root-user", "--mount", "bash", "-c", script, "install-run", src],
                           env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=1200)
        print(r.stdout[-6000:])
        where = ", ".join(b.where() for b in marked)
        if r.returncode != 0:
            print(f"FAIL {where}: exited {r.returncode}")
            return 1
        print(f"ok   {where} (install-run)")
        ran += len(marked)
    print(f"run_doc_examples --install-run: {ran} passed, 0 failed")
    return 0 if ran else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", help="a build directory with libgrass.so")
    parser.add_argument("--scratch", help="where blocks are built (default BUILD/docs-test)")
    parser.add_argument("--cc", default="cc")
    parser.add_argument("--python", default=sys.executable)
    parser.add_argument("--install-run", action="store_true", help="run the install-run blocks as written")
    args = parser.parse_args()
    if args.install_run:
        if not args.scratch:
            parser.error("--install-run needs --scratch")
        return install_run(os.path.abspath(args.scratch))
    if not args.build:
        parser.error("--build is required")
    runner = Runner(args)
    failed, skipped, passed, other = [], [], 0, {}
    for path in doc_files():
        for block in blocks(path):
            if block.lang not in RUN:
                other[block.lang or "(none)"] = other.get(block.lang or "(none)", 0) + 1
                continue
            try:
                status, detail = runner.check(block)
            except (RuntimeError, subprocess.TimeoutExpired) as e:
                failed.append(block)
                print(f"FAIL {block.where()} ({block.lang}): {e}")
                continue
            if status == "skip":
                skipped.append((block, detail))
            else:
                passed += 1
                print(f"ok   {block.where()} ({block.lang}{', ' + block.mark if block.mark else ''})")
    for block, reason in skipped:
        print(f"skip {block.where()} ({block.lang}): {reason}")
    print(f"run_doc_examples: {passed} passed, {len(skipped)} skipped, {len(failed)} failed; not run: " +
          ", ".join(f"{n} {lang}" for lang, n in sorted(other.items())))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
