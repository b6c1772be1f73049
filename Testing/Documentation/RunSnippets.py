"""Runs the programs of a documentation page as written.

A fenced code block preceded by the line `<!-- snippet: NAME -->` is saved
as NAME in a fresh folder. Then every *.py snippet runs with this
interpreter, and when a CMakeLists.txt snippet exists the folder is
configured against the DeepGI build tree, built, and each executable it
makes is run. Also runs the example in vtkdeepgi.enable_gi's docstring.
Each must exit 0 and print "frames".

    RunSnippets.py PAGE.md WORKDIR DEEPGI_DIR CMAKE_GENERATOR
"""
import os
import re
import shutil
import subprocess
import sys
import textwrap

SNIPPET = re.compile(r"<!-- snippet: (\S+) -->\n```[a-z]*\n(.*?)\n```", re.S)


def run(command, cwd, label):
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=600)
    print(result.stdout, end="")
    if result.returncode != 0:
        sys.exit("%s failed (%d):\n%s%s" % (label, result.returncode, result.stdout,
                                            result.stderr))
    return result.stdout


def expect_frames(output, label):
    if "frames" not in output:
        sys.exit("%s printed no frame count:\n%s" % (label, output))


def main():
    page, work, deepgi_dir, generator = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    with open(page) as f:
        snippets = SNIPPET.findall(f.read())
    if not snippets:
        sys.exit("no snippets in %s" % page)
    for name, text in snippets:
        with open(os.path.join(work, name), "w") as f:
            f.write(text + "\n")
    for name, _ in snippets:
        if name.endswith(".py"):
            expect_frames(run([sys.executable, name], work, name), name)
            print("ok: %s ran as written" % name)
    names = [name for name, _ in snippets]
    if "CMakeLists.txt" in names:
        build = os.path.join(work, "build")
        run(["cmake", "-S", work, "-B", build, "-G", generator, "-DDeepGI_DIR=" + deepgi_dir],
            work, "configuring the C++ snippets")
        run(["cmake", "--build", build], work, "building the C++ snippets")
        programs = re.findall(r"add_executable\((\S+)", dict(snippets)["CMakeLists.txt"])
        for program in programs:
            expect_frames(run([os.path.join(build, program)], work, program), program)
            print("ok: %s built and ran as written" % program)

    import vtkdeepgi
    example = textwrap.dedent(vtkdeepgi.enable_gi.__doc__.split("Example::", 1)[1])
    with open(os.path.join(work, "enable_gi_example.py"), "w") as f:
        f.write(example)
    expect_frames(run([sys.executable, "enable_gi_example.py"], work, "enable_gi's example"),
                  "enable_gi's example")
    print("ok: enable_gi's docstring example ran as written")


if __name__ == "__main__":
    main()
