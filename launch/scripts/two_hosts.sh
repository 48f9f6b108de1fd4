#!/usr/bin/env bash
# Two ROS hosts on this machine (./spott run --two-hosts): two network namespaces joined by a
# veth pair, host A at $SPOTT_HOST_A and host B at $SPOTT_HOST_B (default 10.77.0.1 and
# 10.77.0.2, a /24), with an sshd on B that lets roslaunch (paramiko) start B's nodes. Runs
# COMMAND on host A with the ROS environment of a two-host launch; removes everything when
# COMMAND ends. Needs root (namespaces) and openssh-server.
#   [SPOTT_HOST_A=.. SPOTT_HOST_B=..] two_hosts.sh COMMAND [ARGS...]
# COMMAND sees ROS_MASTER_URI=http://A:11311, ROS_IP=A and a HOME whose ~/.ssh knows B; with
# SPOTT_HOSTS_NODES=FILE the script writes there, once the stack is up, every node with the URI
# it serves on (`rosnode list -a`).
set -u
readonly A=${SPOTT_HOST_A:-10.77.0.1} B=${SPOTT_HOST_B:-10.77.0.2} NS_A=spott_host_a NS_B=spott_host_b
die() { echo "two_hosts: $*" >&2; exit 2; }

[[ $# -ge 1 ]] || die "usage: two_hosts.sh COMMAND [ARGS...]"
[[ $(id -u) -eq 0 ]] || die "needs root for network namespaces (ip netns)"
command -v ip >/dev/null || die "needs iproute2 (ip)"
[[ -x /usr/sbin/sshd ]] || die "needs openssh-server (./spott setup installs it)"
ip netns list | grep -qw "$NS_A" && die "namespace $NS_A exists: another two-host run? (ip netns del $NS_A $NS_B)"

tmp=$(mktemp -d /tmp/spott_two_hosts.XXXXXX)
cleanup() {
  [[ -f "$tmp/sshd.pid" ]] && kill "$(cat "$tmp/sshd.pid")" 2>/dev/null
  [[ -n "${probe:-}" ]] && kill "$probe" 2>/dev/null
  ip netns pids "$NS_A" 2>/dev/null | xargs -r kill 2>/dev/null
  ip netns pids "$NS_B" 2>/dev/null | xargs -r kill 2>/dev/null
  sleep 1
  ip netns pids "$NS_A" 2>/dev/null | xargs -r kill -9 2>/dev/null
  ip netns pids "$NS_B" 2>/dev/null | xargs -r kill -9 2>/dev/null
  ip netns del "$NS_A" 2>/dev/null
  ip netns del "$NS_B" 2>/dev/null
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# The network: A <-veth-> B, each with its loopback.
ip netns add "$NS_A" && ip netns add "$NS_B" || die "cannot create network namespaces"
ip link add spott_veth_a netns "$NS_A" type veth peer name spott_veth_b netns "$NS_B" ||
  die "cannot create the veth pair"
for ns in "$NS_A:spott_veth_a:$A" "$NS_B:spott_veth_b:$B"; do
  IFS=: read -r n dev addr <<<"$ns"
  ip -n "$n" link set lo up
  ip -n "$n" addr add "$addr/24" dev "$dev"
  ip -n "$n" link set "$dev" up
done

# Host B's sshd: its own host key, one authorized key, ROS_IP set for the sessions (nodes must
# advertise B's address, not the shared hostname).
mkdir -p /run/sshd "$tmp/home/.ssh"
ssh-keygen -q -t ed25519 -N "" -f "$tmp/host_key" || die "ssh-keygen failed"
ssh-keygen -q -t ed25519 -N "" -f "$tmp/home/.ssh/id_ed25519" || die "ssh-keygen failed"
cp "$tmp/home/.ssh/id_ed25519.pub" "$tmp/authorized_keys"
echo "$B $(cut -d' ' -f1-2 "$tmp/host_key.pub")" >"$tmp/home/.ssh/known_hosts"
printf 'Host %s\n  IdentityFile %s\n' "$B" "$tmp/home/.ssh/id_ed25519" >"$tmp/home/.ssh/config"
chmod 700 "$tmp/home/.ssh"
ip netns exec "$NS_B" /usr/sbin/sshd -f /dev/null -E "$tmp/sshd.log" \
  -o ListenAddress="$B" -o HostKey="$tmp/host_key" -o PidFile="$tmp/sshd.pid" \
  -o AuthorizedKeysFile="$tmp/authorized_keys" -o StrictModes=no -o UsePAM=no \
  -o PermitRootLogin=prohibit-password -o SetEnv="ROS_IP=$B" || die "sshd did not start on $B"
for _ in $(seq 50); do [[ -s "$tmp/sshd.pid" ]] && break; sleep 0.1; done
[[ -s "$tmp/sshd.pid" ]] || die "sshd did not start on $B ($(cat "$tmp/sshd.log" 2>/dev/null))"

# Logs stay where ROS keeps them; only ssh's files come from the temporary HOME.
run_a() {
  ip netns exec "$NS_A" env -u ROS_HOSTNAME HOME="$tmp/home" ROS_HOME="${ROS_HOME:-$HOME/.ros}" \
    ROS_MASTER_URI="http://$A:11311" ROS_IP="$A" "$@"
}
if [[ -n "${SPOTT_HOSTS_NODES:-}" ]]; then
  # Once nodes of both hosts are up, what each serves from.
  run_a bash -c 'for _ in $(seq 600); do
      l=$(rosnode list -a 2>/dev/null)
      if grep -q "'"$A"'" <<<"$l" && grep -q "'"$B"'" <<<"$l" && grep -q harmonic_planner <<<"$l"; then
        sleep 5; rosnode list -a > "$0"; exit 0; fi
      sleep 1; done' "$SPOTT_HOSTS_NODES" &
  probe=$!
fi
run_a "$@"
