#!/usr/bin/env bash
# Hosts for a Spark cluster on one machine: network namespaces with addresses of their own on a
# bridge, whose links can be cut and slowed. As root (Linux, iproute2). Used by the Spark profile's
# NetnsClusterTest; by hand (docs/spark.md, "Across hosts"):
#
#   scripts/spark_netns_cluster.sh up rtc 3          # bridge rtc-br 10.231.77.254/24; hosts rtc-1..rtc-3 = 10.231.77.1..3
#   ip netns exec rtc-1 COMMAND                       # run a command on host 1 (a master, a worker)
#   scripts/spark_netns_cluster.sh cut rtc 2          # host 2's link down (as a pulled cable)
#   scripts/spark_netns_cluster.sh mend rtc 2         # and up again
#   scripts/spark_netns_cluster.sh delay rtc 2 200    # 200 ms more on every packet host 2 sends (tc netem); 0: none
#   scripts/spark_netns_cluster.sh rate rtc 2 2000    # host 2's link at most 2000 kbit/s each way (tc tbf); 0: no limit
#   scripts/spark_netns_cluster.sh down rtc           # every host, its processes and the bridge gone
#
# The root namespace (the driver's host) is 10.231.77.254 on the bridge. Traffic stays on the
# bridge: the hosts have no route elsewhere, and nothing forwards for them. Names: PREFIX-N for a
# host, PREFIX-N-h / PREFIX-N-n for its link's two ends (on the bridge / in the host), PREFIX-br.
set -euo pipefail

usage() { echo "usage: $0 up PREFIX COUNT | down PREFIX | cut PREFIX N | mend PREFIX N | delay PREFIX N MS | rate PREFIX N KBIT" >&2; exit 2; }
[ $# -ge 2 ] || usage
action=$1 prefix=$2
case "$prefix" in [a-z]*) ;; *) echo "$0: PREFIX must start with a lower-case letter: $prefix" >&2; exit 2 ;; esac
[ ${#prefix} -le 8 ] || { echo "$0: PREFIX of at most 8 characters (interface names are at most 15): $prefix" >&2; exit 2; }
subnet=10.231.77

host_number() {
    case "${1:-}" in ''|*[!0-9]*) echo "$0: N must be a host number, got '${1:-}'" >&2; exit 2 ;; esac
    [ "$1" -ge 1 ] && [ "$1" -le 250 ] || { echo "$0: N from 1 to 250, got $1" >&2; exit 2; }
    echo "$1"
}

case "$action" in
up)
    count=$(host_number "${3:-}")
    ip link add "$prefix-br" type bridge
    ip addr add "$subnet.254/24" dev "$prefix-br"
    ip link set "$prefix-br" up
    for n in $(seq 1 "$count"); do
        ip netns add "$prefix-$n"
        ip link add "$prefix-$n-h" type veth peer name "$prefix-$n-n"
        ip link set "$prefix-$n-h" master "$prefix-br" up
        ip link set "$prefix-$n-n" netns "$prefix-$n"
        ip -n "$prefix-$n" addr add "$subnet.$n/24" dev "$prefix-$n-n"
        ip -n "$prefix-$n" link set "$prefix-$n-n" up
        ip -n "$prefix-$n" link set lo up
    done
    ;;
down)
    # Whatever is left: each host's processes, the host (its end of the link goes with it), the bridge.
    for ns in $(ip netns list | awk '{print $1}' | grep -E "^$prefix-[0-9]+$" || true); do
        ip netns pids "$ns" | xargs -r kill -9 2>/dev/null || true
        ip netns del "$ns" 2>/dev/null || true
    done
    ip link del "$prefix-br" 2>/dev/null || true
    ;;
cut)
    ip link set "$prefix-$(host_number "${3:-}")-h" down
    ;;
mend)
    ip link set "$prefix-$(host_number "${3:-}")-h" up
    ;;
delay)
    n=$(host_number "${3:-}")
    ms=${4:-}
    case "$ms" in ''|*[!0-9]*) echo "$0: MS must be a whole number of milliseconds, got '$ms'" >&2; exit 2 ;; esac
    ip netns exec "$prefix-$n" tc qdisc del dev "$prefix-$n-n" root 2>/dev/null || true
    [ "$ms" -eq 0 ] && exit 0
    if ! said=$(ip netns exec "$prefix-$n" tc qdisc add dev "$prefix-$n-n" root netem delay "${ms}ms" 2>&1); then
        # a kernel built without sch_netem answers "Specified qdisc kind is unknown"
        echo "$0: no delay on this machine: tc netem: $said (a slower link: $0 rate $prefix $n KBIT)" >&2
        exit 3
    fi
    ;;
rate)
    n=$(host_number "${3:-}")
    kbit=${4:-}
    case "$kbit" in ''|*[!0-9]*) echo "$0: KBIT must be a whole number of kbit/s, got '$kbit'" >&2; exit 2 ;; esac
    # both ways: what the host sends (its end) and what it is sent (the bridge's end)
    ip netns exec "$prefix-$n" tc qdisc del dev "$prefix-$n-n" root 2>/dev/null || true
    tc qdisc del dev "$prefix-$n-h" root 2>/dev/null || true
    if [ "$kbit" -ne 0 ]; then
        ip netns exec "$prefix-$n" tc qdisc add dev "$prefix-$n-n" root tbf rate "${kbit}kbit" burst 32kbit latency 10s
        tc qdisc add dev "$prefix-$n-h" root tbf rate "${kbit}kbit" burst 32kbit latency 10s
    fi
    ;;
*)
    usage
    ;;
esac
