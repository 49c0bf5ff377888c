"""Every command in clients/python/README.md and docs/python-client.md, and the example, run
as written against a real radiantd (``$RADIANT_SERVER``)."""

from __future__ import annotations

import re
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

from support import (PACKAGE_DIR, SOURCE_DIR, Daemon, checkout_copy, debian_python_env,
                     require_radiantd)

BLOCK = re.compile(r"^```(sh|python)\n(.*?)^```$", re.S | re.M)


def blocks(doc: Path):
    return [(m.group(1), m.group(2)) for m in BLOCK.finditer(doc.read_text())]


class Docs(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        require_radiantd()
        cls.daemon = Daemon().start()

    @classmethod
    def tearDownClass(cls):
        cls.daemon.close()

    def run_doc(self, doc: Path) -> str:
        """Runs the doc's sh and python blocks in order in a fresh copy of the checkout. Python
        blocks run in the doc's .venv when its commands made one, else on the source tree."""
        found = blocks(doc)
        self.assertTrue(found, doc)
        output = []
        with tempfile.TemporaryDirectory(prefix="radiant_py_docs_") as tmp:
            root = checkout_copy(Path(tmp))
            env = debian_python_env(RADIANT_SERVER=self.daemon.url)
            for language, code in found:
                if language == "sh":
                    command = ["bash", "-eo", "pipefail", "-c", code]
                    run_env = env
                else:
                    venv_python = root / ".venv" / "bin" / "python"
                    command = [str(venv_python) if venv_python.exists() else sys.executable, "-c",
                               code]
                    run_env = env if venv_python.exists() else {
                        **env, "PYTHONPATH": str(root / "clients" / "python")}
                done = subprocess.run(command, cwd=root, env=run_env, capture_output=True,
                                      text=True, timeout=600)
                self.assertEqual(done.returncode, 0,
                                 f"{doc.name}:\n{code}\n{done.stdout}\n{done.stderr}")
                output.append(done.stdout)
        return "".join(output)

    def test_readme(self):
        out = self.run_doc(PACKAGE_DIR / "README.md")
        self.assertIn("work plane: E_avg", out)
        self.assertIn("workplane (lux; v up, u across):", out)  # the example's table

    def test_docs_page(self):
        out = self.run_doc(SOURCE_DIR / "docs" / "python-client.md")
        self.assertIn("done ", out)
        self.assertIn("/materials/wall/reflectance reflectance must be in [0, 1)", out)
        self.assertIn("9 rows of 9", out)


class Example(unittest.TestCase):
    def test_first_solve(self):
        require_radiantd()
        example = PACKAGE_DIR / "examples" / "first_solve.py"
        env = {**debian_python_env(), "PYTHONPATH": str(PACKAGE_DIR)}
        with Daemon() as daemon:
            done = subprocess.run(
                [sys.executable, str(example), str(SOURCE_DIR / "proto" / "examples" /
                                                   "furnished-office" / "furnished-office.json"),
                 "--server", daemon.url, "--tolerance", "0.1"],
                env=env, capture_output=True, text=True, timeout=600)
            self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
            lines = done.stdout.splitlines()
            self.assertRegex(lines[0], r"^job [0-9a-f]{32}$")
            self.assertTrue(any(re.match(r"^ *\d+\.\d%  ", line) for line in lines), done.stdout)
            self.assertIn("done: converged", done.stdout)
            self.assertIn("work plane (lux; v up, u across):", done.stdout)
            # A refused scene: exit 2 and radiant validate's lines.
            bad = SOURCE_DIR / "tests" / "data" / "bad" / "reflectance-one.json"
            refused = subprocess.run([sys.executable, str(example), str(bad), "--server",
                                      daemon.url], env=env, capture_output=True, text=True,
                                     timeout=60)
            self.assertEqual(refused.returncode, 2, refused.stdout + refused.stderr)
            self.assertTrue(refused.stderr.startswith(f"{bad}: /materials/wall/reflectance: "),
                            refused.stderr)


if __name__ == "__main__":
    unittest.main()
