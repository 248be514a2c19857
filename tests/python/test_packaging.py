# SPDX-License-Identifier: LGPL-3.0-or-later
"""The Python package as users install it (issue 25): `pip install --no-build-isolation .` into
a fresh virtual environment (offline: --no-index, setuptools and numpy from Debian), the
installed module, its type stubs and py.typed, the example that builds, orders and renders a
mesh, mypy --strict on that example against the installed stubs, the stubs naming every public
name of the extension, and `cmake --install` installing the module.

The wheel is built by setup.py from EXBSP_BUILD_DIR (this build: only the extension is linked
there); a whole build from nothing is what `pip install .` does without it (docs/python.md)."""
import ast
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

import exbsp

ROOT = pathlib.Path(os.environ.get("EXBSP_SOURCE_DIR",
                                   pathlib.Path(__file__).resolve().parents[2]))
BUILD = os.environ.get("EXBSP_BUILD_DIR")
FANDISK = ROOT / "data" / "meshes" / "fandisk.off"
MESH = FANDISK if FANDISK.exists() else ROOT / "tests" / "data" / "cube.off"

needs_build = pytest.mark.skipif(not BUILD, reason="EXBSP_BUILD_DIR is not set (run by ctest)")
not_sanitized = pytest.mark.skipif(
    bool(os.environ.get("EXBSP_SANITIZED")),
    reason="an ASan-built extension in a plain interpreter needs LD_PRELOAD games pip does not")


def _copy_sources(dest: pathlib.Path) -> None:
    """The source tree without build folders, the corpus and git's files (what a clone has)."""
    ignore = shutil.ignore_patterns(".git", "build", "build-*", "data", "__pycache__",
                                    "*.egg-info", "node_modules")
    shutil.copytree(ROOT, dest, ignore=ignore)


@pytest.fixture(scope="module")
def venv(tmp_path_factory: pytest.TempPathFactory) -> pathlib.Path:
    work = tmp_path_factory.mktemp("pip")
    src = work / "src"
    _copy_sources(src)
    env_dir = work / "venv"
    # Debian's numpy is the module's one dependency: the environment sees the system's packages.
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(env_dir)],
                   check=True)
    python = env_dir / "bin" / "python"
    env = dict(os.environ, EXBSP_CMAKE_BUILD_DIR=str(BUILD))
    env.pop("PYTHONPATH", None)  # the installed package, not the build tree's
    done = subprocess.run([str(python), "-m", "pip", "install", "--no-build-isolation",
                           "--no-deps", "--no-index", str(src)],
                          env=env, capture_output=True, text=True, cwd=work)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return python


def _run(python: pathlib.Path, *args: str, cwd: pathlib.Path) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    env.pop("PYTHONPATH", None)
    return subprocess.run([str(python), *args], env=env, cwd=cwd, capture_output=True, text=True)


@needs_build
@not_sanitized
def test_pip_installs_the_module_its_stubs_and_py_typed(venv: pathlib.Path, tmp_path) -> None:
    done = _run(venv, "-c", "import exbsp, pathlib; p = pathlib.Path(exbsp.__file__).parent; "
                "print(exbsp.version); print(sorted(f.name for f in p.iterdir()))", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    version, files = done.stdout.splitlines()
    assert version == exbsp.version
    for name in ("__init__.py", "__init__.pyi", "_exbsp.pyi", "distributed.py", "drawing_sets.py",
                 "py.typed"):
        assert name in files
    assert any(f.startswith("_exbsp") and f.endswith(".so") for f in eval(files))
    assert "site-packages" in _run(venv, "-c", "import exbsp; print(exbsp.__file__)",
                                   cwd=tmp_path).stdout


@needs_build
@not_sanitized
def test_the_installed_package_builds_orders_and_renders_a_mesh(venv: pathlib.Path,
                                                                tmp_path) -> None:
    example = ROOT / "examples" / "python" / "render_fandisk.py"
    done = _run(venv, str(example), str(MESH), str(tmp_path / "out"), cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    png = (tmp_path / "out.png").read_bytes()
    assert png.startswith(b"\x89PNG\r\n\x1a\n")
    svg = (tmp_path / "out_front.svg").read_text()
    assert svg.startswith("<?xml") and "<path" in svg and svg.rstrip().endswith("</svg>")
    assert "painted pixels" in done.stdout


@needs_build
@not_sanitized
def test_mypy_strict_passes_on_the_example_against_the_installed_stubs(venv: pathlib.Path,
                                                                       tmp_path) -> None:
    pytest.importorskip("mypy", reason="mypy (Debian's python3-mypy, scripts/setup) is missing")
    example = ROOT / "examples" / "python" / "render_fandisk.py"
    env = dict(os.environ)
    env.pop("PYTHONPATH", None)
    done = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental",
                           "--cache-dir", str(tmp_path / "cache"), "--python-executable",
                           str(venv), str(example)], env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    # And the stubs are what mypy read: a wrong use of render's return types is an error.
    wrong = tmp_path / "wrong.py"
    wrong.write_text("import exbsp\n"
                     "t = exbsp.load('t.exbsp')\n"
                     "svg: bytes = t.render(format='svg')\n")
    done = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental",
                           "--cache-dir", str(tmp_path / "cache"), "--python-executable",
                           str(venv), str(wrong)], env=env, capture_output=True, text=True)
    assert done.returncode == 1 and "Incompatible types in assignment" in done.stdout, done.stdout


def test_the_stubs_name_every_public_name_of_the_extension_and_nothing_else() -> None:
    stub = ROOT / "src" / "python" / "exbsp" / "_exbsp.pyi"
    tree = ast.parse(stub.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
        elif isinstance(node, ast.Assign):
            names.update(t.id for t in node.targets if isinstance(t, ast.Name))
    aliases = {"PathArg", "Vec3", "RGB", "Faces"}  # type aliases of the stub only
    runtime = {n for n in dir(exbsp._exbsp) if not n.startswith("_")} | {"__version__"}
    assert runtime - names == set(), "public names without a stub"
    assert names - aliases - runtime == set(), "stubs of names the extension lacks"
    # The Tree class: every public method and property is in the stub.
    tree_stub = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "Tree")
    stub_members = {n.name for n in tree_stub.body if isinstance(n, ast.FunctionDef)}
    members = {n for n in dir(exbsp.Tree) if not n.startswith("_")}
    assert members - stub_members == set()


@needs_build
@not_sanitized
def test_cmake_install_installs_the_python_package(tmp_path) -> None:
    prefix = tmp_path / "prefix"
    done = subprocess.run(["cmake", "--install", str(BUILD), "--prefix", str(prefix)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    site = prefix / "lib" / "python3" / "dist-packages"
    assert (site / "exbsp" / "py.typed").exists()
    env = dict(os.environ, PYTHONPATH=str(site))
    done = subprocess.run([sys.executable, "-c", "import exbsp; print(exbsp.__file__)"],
                          env=env, capture_output=True, text=True, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith(str(site))
