# Copyright (c) 2026 The CGAL BODT_3 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""`pip install .`: the Python package bodt, built by the project's own CMake build.

The compiled part, bodt._bodt, is the CMake target `_bodt` (python/CMakeLists.txt),
configured for the Python that runs pip and built in build-python/ beside the usual
build/ (the same depth, so that ccache finds what a build in build/ compiled); the
rest of the package is python/bodt/. It needs what scripts/setup.sh installs (CGAL,
pybind11, ...): on Debian, `python3 -m venv --system-site-packages` and
`pip install --no-build-isolation .` work offline.
"""

import os
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
CMAKE_BUILD = os.path.join(ROOT, "build-python")


def project_version():
    """The version of CMakeLists.txt's project(), the one `bodt --version` prints."""
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        return re.search(r"project\(CGAL_BODT_3 VERSION ([0-9.]+)", f.read()).group(1)


class CMakeExtension(Extension):
    """An extension module that CMake builds: setuptools compiles nothing itself."""

    def __init__(self, name, target):
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    """Configures and builds the CMake target of each CMakeExtension, then copies the module."""

    def build_extension(self, ext):
        if shutil.which("cmake") is None:
            raise RuntimeError("bodt: cmake is missing; run `bash scripts/setup.sh` (Debian) or install CMake")
        configure = ["cmake", "-S", ROOT, "-B", CMAKE_BUILD, "-DCMAKE_BUILD_TYPE=Release",
                     "-DPython3_EXECUTABLE=" + sys.executable, "-DBODT_BUILD_PYTHON=ON", "-DBODT_BUILD_TESTS=OFF"]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", CMAKE_BUILD, "--target", ext.target, "-j", jobs], check=True)
        built = os.path.join(CMAKE_BUILD, "python", "bodt", ext.target + sysconfig.get_config_var("EXT_SUFFIX"))
        if not os.path.isfile(built):
            raise RuntimeError("bodt: CMake did not build %s" % built)
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built, target)


setup(
    version=project_version(),
    packages=["bodt"],
    package_dir={"": "python"},
    ext_modules=[CMakeExtension("bodt._bodt", "_bodt")],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own files next to CMake's, not in build/, which is CMake's.
    options={"build": {"build_base": os.path.join("build-python", "setuptools")}},
    zip_safe=False,
)
