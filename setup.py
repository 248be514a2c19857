# SPDX-License-Identifier: LGPL-3.0-or-later
"""Builds the Python package exbsp with CMake (docs/python.md "Installing").

    pip install --no-build-isolation .

setuptools alone cannot build exbsp: the extension is compiled from the C++ tree with its CMake
options (exact arithmetic flags, CGAL, GMP), so build_ext configures CMake in a build folder
and builds the one target exbsp_python, then copies _exbsp.*.so into the wheel beside the pure
Python files of src/python/exbsp (with their type stubs). Environment:
  EXBSP_CMAKE_BUILD_DIR  a CMake build folder to configure (if it is not yet) and build in, e.g.
                         an existing build/ (then only the extension is linked); default: a
                         folder under setuptools' build_temp (a whole build, several minutes).
  EXBSP_BUILD_JOBS       parallel jobs (default: the number of CPUs).
"""
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        m = re.search(r"project\(exbsp VERSION ([0-9.]+)", f.read())
    if not m:
        raise RuntimeError("CMakeLists.txt: no 'project(exbsp VERSION x.y.z)'")
    return m.group(1)


class cmake_build_ext(build_ext):
    """build_ext for the one extension exbsp._exbsp, by CMake."""

    def build_extension(self, ext):
        build_dir = os.environ.get("EXBSP_CMAKE_BUILD_DIR") or os.path.join(
            os.path.abspath(self.build_temp), "cmake")
        os.makedirs(build_dir, exist_ok=True)
        jobs = os.environ.get("EXBSP_BUILD_JOBS") or str(os.cpu_count() or 1)
        if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.check_call(
                ["cmake", "-S", ROOT, "-B", build_dir, *generator, "-DCMAKE_BUILD_TYPE=Release",
                 "-DEXBSP_BUILD_PYTHON=ON", "-DEXBSP_BUILD_TESTS=OFF", "-DEXBSP_BUILD_BENCH=OFF",
                 "-DPython_EXECUTABLE=" + sys.executable])
        subprocess.check_call(["cmake", "--build", build_dir, "--target", "exbsp_python",
                               "--parallel", jobs])
        package = os.path.join(build_dir, "src", "python", "exbsp")
        built = [f for f in os.listdir(package) if f.startswith("_exbsp") and f.endswith(".so")]
        if len(built) != 1:
            raise RuntimeError(f"{package}: expected one _exbsp*.so, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(package, built[0]), target)


setup(
    name="exbsp",
    version=project_version(),
    description="Exact-predicate BSP trees, orders, sections, renders and drawing sheets of "
                "triangle meshes",
    # The module links the GPL component (section caps, DXF): GPL as distributed; its own
    # sources are LGPL (docs/licence.md).
    license="GPL-3.0-or-later",
    python_requires=">=3.7",
    install_requires=["numpy"],
    package_dir={"": "src/python"},
    packages=["exbsp"],
    package_data={"exbsp": ["py.typed", "*.pyi"]},
    ext_modules=[Extension("exbsp._exbsp", sources=[])],
    cmdclass={"build_ext": cmake_build_ext},
    zip_safe=False,
)
