"""The compiled part of `pip install .` (pyproject.toml): CMake builds the target hecal_python
and setuptools installs the module it made. HECAL_BUILD_DIR (default build/) is configured with
the installing Python when it has no CMakeCache.txt yet, else reused as it is."""
import glob
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.path.abspath(os.environ.get("HECAL_BUILD_DIR", os.path.join(ROOT, "build")))
        if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.check_call(["cmake", "-S", ROOT, "-B", build, *generator,
                                   "-DCMAKE_BUILD_TYPE=Release", "-DHECAL_BUILD_TESTS=OFF",
                                   f"-DPython3_EXECUTABLE={sys.executable}"])
        subprocess.check_call(["cmake", "--build", build, "--target", "hecal_python"])
        built = glob.glob(os.path.join(build, "python", "hecal", "_hecal*.so"))
        if not built:
            raise RuntimeError(f"hecal_python built nothing in {build}/python/hecal")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


# setuptools' own files (build/lib.*, *.egg-info) under build/setuptools, not in the sources.
SETUPTOOLS_DIR = os.path.join("build", "setuptools")
os.makedirs(os.path.join(ROOT, SETUPTOOLS_DIR), exist_ok=True)
setup(ext_modules=[Extension("hecal._hecal", sources=[])], cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": SETUPTOOLS_DIR}, "egg_info": {"egg_base": SETUPTOOLS_DIR}})
