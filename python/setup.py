"""Builds the extension `boolean_isosurfacing._core` with the project's CMake.

Everything else (metadata, the pure-Python package) is in pyproject.toml.
Environment: BISO_CMAKE_ARGS (extra CMake arguments, e.g.
"-DBISO_SHARED_DATA_DIR=..."), CMAKE_BUILD_PARALLEL_LEVEL (default 2).
"""

import glob
import os
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)  # the project's top-level CMakeLists.txt


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.path.abspath(os.path.join(self.build_temp, "cmake"))
        configure = [
            "cmake", "-S", ROOT, "-B", build_dir,
            "-DCMAKE_BUILD_TYPE=Release",
            "-DBISO_BUILD_PYTHON=ON",
            "-DBISO_BUILD_TESTS=OFF",
            "-DBISO_BUILD_EXAMPLES=OFF",
            "-DBISO_BUILD_BENCHMARKS=OFF",
            # the interpreter pip runs is the one that will import the module
            f"-DPython_EXECUTABLE={sys.executable}",
        ] + shlex.split(os.environ.get("BISO_CMAKE_ARGS", ""))
        subprocess.check_call(configure)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        subprocess.check_call(["cmake", "--build", build_dir, "--target", "_core", "-j", jobs])
        built = glob.glob(os.path.join(build_dir, "python", "boolean_isosurfacing", "_core*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one built _core module in {build_dir}, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


setup(ext_modules=[CMakeExtension("boolean_isosurfacing._core")], cmdclass={"build_ext": CMakeBuild})
