"""Builds the Python module gpdr for pip, from a clone of gpdr:

    python3 -m venv --system-site-packages /tmp/venv-gpdr
    /tmp/venv-gpdr/bin/pip install --no-build-isolation .

build_ext runs the project's own CMake build (GPDR_PYTHON=ON, the target
gpdr_python only, for the interpreter running this) in build-pip/, and
build_py adds the samples get_data() offers.  Nothing is downloaded: CMake,
a C++20 compiler, fmt, CLI11 and pybind11 come from the system
(scripts/setup.sh installs them), and numpy from the system's site
packages.  See docs/python.md.
"""
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

ROOT = os.path.dirname(os.path.abspath(__file__))
# The samples of get_data(): poly-samples/ and the classic inputs of tests/data/.
SAMPLE_FOLDERS = ("poly-samples", os.path.join("tests", "data"))


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        return re.search(r"project\(gpdr VERSION ([0-9.]+)", f.read()).group(1)


class CMakeExtension(Extension):
    """An extension CMake builds: no sources for setuptools to compile."""

    def __init__(self, name, target):
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.path.abspath(os.path.join(self.build_temp, "cmake"))
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.check_call([
            "cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
            "-DGPDR_BUILD_TESTS=OFF", "-DGPDR_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}",
        ])
        subprocess.check_call(["cmake", "--build", build_dir, "--target", ext.target, "-j", jobs])
        file_name = os.path.basename(self.get_ext_filename(ext.name))
        built = os.path.join(build_dir, "python", "gpdr", file_name)
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built, target)


class BuildWithSamples(build_py):
    def run(self):
        super().run()
        data = os.path.join(self.build_lib, "gpdr", "data")
        os.makedirs(data, exist_ok=True)
        for folder in SAMPLE_FOLDERS:
            for name in sorted(os.listdir(os.path.join(ROOT, folder))):
                if name.endswith((".poly", ".node")):
                    shutil.copyfile(os.path.join(ROOT, folder, name), os.path.join(data, name))


setup(
    name="gpdr",
    version=project_version(),
    description="Triangle's meshes from gpdr, a parallel drop-in replacement for Triangle 1.6, "
                "with the triangle package's interface",
    license="MIT",
    python_requires=">=3.7",
    install_requires=["numpy"],
    packages=["gpdr"],
    package_dir={"gpdr": "python/gpdr"},
    ext_modules=[CMakeExtension("gpdr._core", target="gpdr_python")],
    cmdclass={"build_ext": CMakeBuild, "build_py": BuildWithSamples},
    # Not build/: that is the project's own CMake build folder.
    options={"build": {"build_base": "build-pip"}},
    zip_safe=False,
)
