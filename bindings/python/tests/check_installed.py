# SPDX-License-Identifier: Apache-2.0
"""Installs the build into a staging prefix (cmake --install) and imports the installed
package from a clean interpreter, with neither ENTERON_LIBRARY nor the source tree in
sight: it must load the installed library found next to the package.

usage: check_installed.py BUILD_DIR WORK_DIR PYTHONDIR LIBDIR [BINDIR]   (CMAKE: the cmake to use)

With BINDIR, the installed enteron-calibrate must find the installed package too.
"""
import os
import shutil
import subprocess
import sys

build_dir, work_dir, python_dir, lib_dir = sys.argv[1:5]
cmake = os.environ.get("CMAKE", "cmake")
stage = os.path.join(work_dir, "stage")
shutil.rmtree(work_dir, ignore_errors=True)
os.makedirs(work_dir)
subprocess.run([cmake, "--install", build_dir, "--prefix", stage], check=True, stdout=subprocess.DEVNULL)

package_dir = os.path.join(stage, python_dir)
environment = {key: value for key, value in os.environ.items() if not key.startswith(("ENTERON_", "PYTHON"))}
environment["PYTHONPATH"] = package_dir
environment["PYTHONDONTWRITEBYTECODE"] = "1"
program = (
    "import enteron\n"
    "with enteron.Scene({'intestine': {'length': 1.0, 'control_points': 10}, 'gravity': [0, 0, -9.81]}) as s:\n"
    "    s.step(0.01)\n"
    "    print(enteron.library_path)\n"
    "    print(enteron.__file__)\n"
)
result = subprocess.run([sys.executable, "-c", program], cwd=work_dir, env=environment,
                        check=True, capture_output=True, text=True)
library, package = result.stdout.split()
expected_lib = os.path.realpath(os.path.join(stage, lib_dir))
if os.path.dirname(os.path.realpath(library)) != expected_lib:
    sys.exit("FAIL: the installed package loaded %s, expected a library in %s" % (library, expected_lib))
if not os.path.realpath(package).startswith(os.path.realpath(package_dir)):
    sys.exit("FAIL: imported %s, expected the package in %s" % (package, package_dir))
print("installed package %s loads %s" % (package, library))

if len(sys.argv) > 5:
    launcher = os.path.join(stage, sys.argv[5], "enteron-calibrate")
    environment.pop("PYTHONPATH")
    shown = subprocess.run([launcher, "--help"], cwd=work_dir, env=environment, capture_output=True, text=True)
    if shown.returncode != 0 or "EXPERIMENT" not in shown.stdout.upper():
        sys.exit("FAIL: %s --help: status %d: %s" % (launcher, shown.returncode, shown.stderr))
    print("installed %s finds the installed package" % launcher)
