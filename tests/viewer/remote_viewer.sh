#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# viewer.remote_lcm: enteron-viewer --lcm shows a running enteron-lcm-server and drives its
# tool (docs/viewer.md, "A remote session"). Real processes over udpm, inside a network
# namespace made here (nothing can leave it); exit 77 (ctest: skipped) where one cannot be
# made. The checks are remote_viewer_test.py's.
#   remote_viewer.sh WORK_DIR
# Environment: SERVER, VIEWER, SCENE, TYPES (the generated Python message types).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lcm/network_namespace.sh"
enter_network_namespace viewer.remote_lcm "$@"
exec /usr/bin/python3 "$(dirname "${BASH_SOURCE[0]}")/remote_viewer_test.py" "$@"
