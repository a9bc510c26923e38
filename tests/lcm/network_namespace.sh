# SPDX-License-Identifier: Apache-2.0
# Sourced by the tests that use udpm (udpm_session.sh, lcm_spy.sh): runs the calling script
# again inside a network namespace of its own (unshare -n) with the loopback up and the
# multicast range routed to it, so that nothing the test sends can leave the namespace; or
# exits 77 (ctest: skipped) saying why that is not possible here.
#   enter_network_namespace TEST_NAME "$@"
enter_network_namespace() {
  local name="$1"
  shift
  if [[ "${ENTERON_IN_NAMESPACE:-}" != 1 ]]; then
    command -v ip >/dev/null || { echo "$name: SKIPPED: no ip command (iproute2)"; exit 77; }
    if ! unshare -n true 2>/dev/null; then
      echo "$name: SKIPPED: cannot make a network namespace here (unshare -n needs CAP_SYS_ADMIN);" \
           "udpm is tested only inside one, never on a real network"
      exit 77
    fi
    exec unshare -n env ENTERON_IN_NAMESPACE=1 "$0" "$@"
  fi
  ip link set lo up
  ip route add 224.0.0.0/4 dev lo
}
