"""The package installs offline into a fresh venv over Debian's setuptools, and works there."""

from __future__ import annotations

import subprocess
import tempfile
import unittest
from pathlib import Path

from support import Daemon, checkout_copy, debian_python_env, require_radiantd


class Install(unittest.TestCase):
    def test_offline_pip_install_into_a_venv(self):
        require_radiantd()
        with tempfile.TemporaryDirectory(prefix="radiant_py_install_") as tmp, Daemon() as daemon:
            root = checkout_copy(Path(tmp))
            env = debian_python_env(RADIANT_SERVER=daemon.url)
            venv = root / "venv"

            def run(*command: str) -> str:
                done = subprocess.run(command, cwd=root, env=env, capture_output=True, text=True,
                                      timeout=300)
                self.assertEqual(done.returncode, 0, f"{command}\n{done.stdout}\n{done.stderr}")
                return done.stdout

            run("python3", "-m", "venv", "--system-site-packages", str(venv))
            run(str(venv / "bin" / "pip"), "install", "--no-build-isolation", "--no-index",
                "clients/python")
            out = run(str(venv / "bin" / "python"), "-c",
                      "import radiant_client as r; print(r.__file__); print(r.Client().health())")
            where, health = out.splitlines()
            self.assertTrue(where.startswith(str(venv)), where)  # the installed copy
            self.assertEqual(health, "{'status': 'ok', 'store': 'writable'}")
            # Typed: the marker file is installed.
            self.assertTrue((Path(where).parent / "py.typed").is_file())


if __name__ == "__main__":
    unittest.main()
