"""The Pythonic layer under random call sequences (fuzz_calls.py): 10,000 sequences by default
(GRASS_PYTHON_FUZZ_SEQUENCES changes it), most on CPU contexts in two interpreters, 200 with
a headless GL context in a third, each under faulthandler. A signal (the interpreter killed)
or an exception other than a GrassError fails the test with the seed and the calls."""
import os
import subprocess
import sys

from conftest import HERE, PACKAGE_ROOT

GL_SEQUENCES = 200


def test_random_call_sequences_raise_grass_errors_and_never_a_signal():
    total = int(os.environ.get("GRASS_PYTHON_FUZZ_SEQUENCES", "10000"))
    gl = min(GL_SEQUENCES, total // 10)
    cpu = total - gl
    runs = [(0, cpu // 2), (cpu // 2, cpu - cpu // 2), (10 ** 6, gl, "--gl")]
    env = dict(os.environ, PYTHONPATH=PACKAGE_ROOT, PYTHONFAULTHANDLER="1")
    script = os.path.join(HERE, "fuzz_calls.py")
    processes = [subprocess.Popen([sys.executable, script, str(first), str(count), *rest], env=env,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
                 for first, count, *rest in runs if count]
    outputs = [(p, *p.communicate(timeout=600)) for p in processes]
    for p, out, err in outputs:
        assert p.returncode == 0, f"{' '.join(p.args[1:])} ended with {p.returncode}:\n{out[-3000:]}{err[-6000:]}"
        assert out.startswith("ok: ") and not err, out + err[-6000:]  # err: a callback's exception escaped
    print(*(out for _, out, _ in outputs))
    done = sum(int(out.split()[1]) for _, out, _ in outputs)
    assert done == total
