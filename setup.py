"""Builds the extension rdmesh._rdmesh with the project's CMake build (python/CMakeLists.txt).

pip install --no-build-isolation .    configures a Release build in build-pip/cmake
                                      (tests off) and builds the _rdmesh target only.
RDMESH_CMAKE_BUILD_DIR=DIR            reuses an already configured build folder
                                      instead (its settings untouched): only _rdmesh
                                      is brought up to date there.
RDMESH_JOBS=N                         parallel jobs (default 2).
"""

import glob
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.environ.get("RDMESH_CMAKE_BUILD_DIR")
        if build_dir:
            build_dir = pathlib.Path(build_dir).resolve()
        else:
            build_dir = ROOT / "build-pip" / "cmake"
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir),
                            "-DCMAKE_BUILD_TYPE=Release", "-DRDMESH_BUILD_TESTS=OFF",
                            "-DRDMESH_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}"],
                           check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "_rdmesh", "-j",
                        os.environ.get("RDMESH_JOBS", "2")], check=True)
        built = glob.glob(str(build_dir / "python" / "rdmesh" / "_rdmesh*.so"))
        if len(built) != 1:
            sys.exit(f"rdmesh: expected one _rdmesh*.so in {build_dir}/python/rdmesh, got {built}")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(ext_modules=[Extension("rdmesh._rdmesh", sources=[])], cmdclass={"build_ext": CMakeBuild})
