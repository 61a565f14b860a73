#!/usr/bin/env bash
# A throw-away, one-node SLURM cluster on 127.0.0.1 for testing abglib's SLURM profile
# (profiles/slurm) -- the cluster tests/test_slurm.py and .ci/run use. Debian 12, as root.
#
#   tools/slurm-cluster.sh install   apt-get the Debian packages (only the missing ones)
#   tools/slurm-cluster.sh start     write the configs, start munged, mariadbd, slurmdbd,
#                                    slurmctld and slurmd, wait for an idle node
#   tools/slurm-cluster.sh status    each daemon, the node, the account; exit 1 if one is down
#   tools/slurm-cluster.sh stop      cancel leftover jobs, stop the daemons this script
#                                    started, by the PIDs it recorded, and nothing else
#   tools/slurm-cluster.sh link      only point /etc/slurm/slurm.conf here (start does it)
#
# Everything the cluster writes lives in one directory, $ABGLIB_SLURM_DIR (default
# /tmp/abglib-slurm): configs (etc/), munge key and socket, the MariaDB data directory,
# controller and node spool, logs (log/) and the daemons' PID files (pid/). munge runs on
# a private socket and key, MariaDB on a private data directory; nothing goes to /run or
# /var. One thing lives outside while the cluster runs: the symlink /etc/slurm/slurm.conf
# -> etc/slurm.conf, because the Slurm commands that the tests and the profile run (sbatch,
# sacct, scancel, from processes that do not inherit this script's SLURM_CONF) must find
# the config at its default path, where real clusters keep theirs. `start` refuses to replace an /etc/slurm/slurm.conf it did not make, and `stop`
# removes the symlink. A run killed before its `stop` (a CI job or session that ended in
# the middle of the SLURM test) leaves the symlink behind, pointing at its own directory:
# `start` takes such a link over when none of that cluster's daemons runs; when some still
# run it stops them under CI=true and otherwise says how to. Deleting the directory after `stop` leaves only the apt packages.
#
# The cluster: ClusterName abglib, node `localhost` (127.0.0.1) with this machine's CPUs and
# memory (from `slurmd -C`), partition `debug` (default) and `batch` (the same node, not the
# default), account `ci` with root in it (root's default account stays `root`, so that a
# test can tell SBATCH_ACCOUNT / SBATCH_PARTITION from the defaults).
# Accounting runs through slurmdbd on MariaDB, so `sacct` answers as on a real cluster (the
# profile polls job states with sacct; without it the workflow hangs).
# EnforcePartLimits=ALL rejects a job that asks for more than the node has at submission
# instead of leaving it pending for ever. No systemd, no cgroups (works in containers).
#
# Knobs: ABGLIB_SLURM_DIR, ABGLIB_SLURM_PORT (first of four TCP ports on 127.0.0.1:
# slurmctld, slurmd, slurmdbd, MariaDB; default 16817), ABGLIB_SLURM_TIMEOUT (seconds to
# wait for each daemon, default 60), ABGLIB_SLURM_DEFAULT_CONF (the path the jobs' Slurm
# commands read, default /etc/slurm/slurm.conf; tests/test_slurm_cluster.py moves it).
set -euo pipefail

DIR=${ABGLIB_SLURM_DIR:-/tmp/abglib-slurm}
PORT=${ABGLIB_SLURM_PORT:-16817}
TIMEOUT=${ABGLIB_SLURM_TIMEOUT:-60}
CLUSTER=abglib
PARTITION=debug
PARTITION2=batch
ACCOUNT=ci
NODE=localhost
PACKAGES=(slurm-wlm slurmdbd munge mariadb-server)
DAEMONS=(munged mariadbd slurmdbd slurmctld slurmd) # start order; stop goes backwards

ETC=$DIR/etc
PIDS=$DIR/pid
LOGS=$DIR/log
MUNGE_SOCKET=$DIR/munge/munge.socket
DB_DATA=$DIR/mariadb
DB_RUN=$DIR/mariadb-run # the mysql user's: socket, pid file, error log, temporary files
DB_SOCKET=$DB_RUN/mariadb.sock
DB_PORT=$((PORT + 3))
DB_PASS=abglib-loopback # a database on 127.0.0.1 that lives as long as the directory
DEFAULT_CONF=${ABGLIB_SLURM_DEFAULT_CONF:-/etc/slurm/slurm.conf}
# the daemons read their configs from here (slurmdbd finds slurmdbd.conf beside it)
export SLURM_CONF=$ETC/slurm.conf

say() { printf 'slurm-cluster %(%H:%M:%S)T %s\n' -1 "$*" >&2; }
fail() {
    say "error: $*"
    exit 1
}

# running NAME -> the PID recorded for daemon NAME, if that process is alive, not a zombie
# and still NAME (a recycled PID is not ours).
running() {
    local file=$PIDS/$1.pid pid state
    [[ -s $file ]] || return 1
    pid=$(tr -dc 0-9 <"$file")
    [[ -n $pid && $(cat "/proc/$pid/comm" 2>/dev/null) == "$1" ]] || return 1
    state=$(cat "/proc/$pid/stat" 2>/dev/null) || return 1
    state=${state##*) }
    [[ ${state%% *} != Z ]] || return 1
    echo "$pid"
}

# until_ok [-d DAEMON] WHAT CMD... -> retry CMD every 0.3 s for TIMEOUT seconds; give up
# early if DAEMON has died.
until_ok() {
    local daemon=
    if [[ $1 == -d ]]; then
        daemon=$2
        shift 2
    fi
    local what=$1 deadline=$((SECONDS + TIMEOUT))
    shift
    until "$@" >/dev/null 2>&1; do
        if [[ -n $daemon ]] && ! running "$daemon" >/dev/null; then
            say "$daemon exited while starting (logs in $LOGS)"
            return 1
        fi
        ((SECONDS < deadline)) || {
            say "$what: no answer after ${TIMEOUT}s"
            return 1
        }
        sleep 0.3
    done
    say "$what: up"
}

# record NAME FILE -> wait for the PID file a forking daemon writes, keep its PID in pid/
record() {
    until_ok "$1 pid file" test -s "$2" || fail "$1 did not start (logs in $LOGS)"
    tr -dc 0-9 <"$2" >"$PIDS/$1.pid"
}

do_install() {
    local p missing=()
    for p in "${PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q '^install ok installed' ||
            missing+=("$p")
    done
    if ((${#missing[@]})); then
        say "apt-get install ${missing[*]}"
        # policy-rc.d keeps the packages' own services from starting (we start our own)
        DEBIAN_FRONTEND=noninteractive apt-get update -qq
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
            "${missing[@]}" >"${TMPDIR:-/tmp}/abglib-slurm-apt.log" 2>&1 ||
            fail "apt-get install failed: $(tail -5 "${TMPDIR:-/tmp}/abglib-slurm-apt.log")"
        rm -f "${TMPDIR:-/tmp}/abglib-slurm-apt.log"
    fi
}

write_configs() {
    local hw
    # the node as slurmd sees it; a node declared bigger than it is would be drained
    hw=$(slurmd -C | head -1 | sed 's/^NodeName=[^ ]* //')
    [[ $hw == *CPUs=*RealMemory=* ]] || fail "unexpected output of slurmd -C: $hw"
    cat >"$ETC/slurm.conf.new" <<EOF
# written by tools/slurm-cluster.sh (rewritten on every start)
ClusterName=$CLUSTER
SlurmctldHost=$NODE(127.0.0.1)
SlurmctldPort=$PORT
SlurmdPort=$((PORT + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$MUNGE_SOCKET
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
JobAcctGatherType=jobacct_gather/linux
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/slurmdbd
AccountingStorageHost=$NODE
AccountingStoragePort=$((PORT + 2))
# for slurmdbd connections the clients take the munge socket from here, not from AuthInfo
AccountingStoragePass=$MUNGE_SOCKET
AccountingStorageEnforce=associations
EnforcePartLimits=ALL
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
MinJobAge=300
MailProg=/bin/true
StateSaveLocation=$DIR/slurmctld
SlurmdSpoolDir=$DIR/slurmd
SlurmctldPidFile=$DIR/slurmctld/slurmctld.pid
SlurmdPidFile=$DIR/slurmd/slurmd.pid
SlurmctldLogFile=$LOGS/slurmctld.log
SlurmdLogFile=$LOGS/slurmd.log
NodeName=$NODE NodeAddr=127.0.0.1 $hw State=UNKNOWN
PartitionName=$PARTITION Nodes=$NODE Default=YES MaxTime=INFINITE State=UP
PartitionName=$PARTITION2 Nodes=$NODE Default=NO MaxTime=INFINITE State=UP
EOF
    if cmp -s "$ETC/slurm.conf.new" "$ETC/slurm.conf"; then
        rm "$ETC/slurm.conf.new"
    else
        mv "$ETC/slurm.conf.new" "$ETC/slurm.conf"
        # a controller still running from an earlier start reads the new one
        if running slurmctld >/dev/null; then scontrol reconfigure >/dev/null || true; fi
    fi
    # slurmdbd reads slurmdbd.conf beside $SLURM_CONF; it must be 0600
    (
        umask 077
        cat >"$ETC/slurmdbd.conf" <<EOF
# written by tools/slurm-cluster.sh
AuthType=auth/munge
AuthInfo=socket=$MUNGE_SOCKET
DbdHost=$NODE
DbdAddr=127.0.0.1
DbdPort=$((PORT + 2))
SlurmUser=root
PidFile=$DIR/slurmdbd.pid
LogFile=$LOGS/slurmdbd.log
StorageType=accounting_storage/mysql
StorageHost=127.0.0.1
StoragePort=$DB_PORT
StorageUser=slurm
StoragePass=$DB_PASS
StorageLoc=slurm_acct_db
EOF
    )
}

start_munged() {
    running munged >/dev/null && return
    mkdir -p "$DIR/munge"
    chmod 700 "$DIR/munge"
    [[ -s $DIR/munge/munge.key ]] || mungekey --create --keyfile="$DIR/munge/munge.key"
    chmod 600 "$DIR/munge/munge.key"
    rm -f "$DIR/munge/munged.pid"
    # as root (SlurmUser is root); --force: munged would refuse a socket under /tmp
    munged --force --num-threads=10 --socket="$MUNGE_SOCKET" --key-file="$DIR/munge/munge.key" \
        --pid-file="$DIR/munge/munged.pid" --seed-file="$DIR/munge/munged.seed" \
        --log-file="$LOGS/munged.log" 2>>"$LOGS/munged.log"
    record munged "$DIR/munge/munged.pid"
    until_ok -d munged "munge" sh -c "munge -S '$MUNGE_SOCKET' -n | unmunge -S '$MUNGE_SOCKET'" ||
        fail "munge does not work (see $LOGS/munged.log)"
}

db() { mariadb --no-defaults --protocol=socket --socket="$DB_SOCKET" -uroot "$@"; }

start_mariadbd() {
    running mariadbd >/dev/null && return
    if [[ ! -d $DB_DATA/mysql ]]; then
        install -d -o mysql -g mysql "$DB_DATA"
        mariadb-install-db --no-defaults --user=mysql --datadir="$DB_DATA" --skip-test-db \
            --auth-root-authentication-method=socket >"$LOGS/mariadb-install-db.log" 2>&1 ||
            fail "mariadb-install-db failed (see $LOGS/mariadb-install-db.log)"
    fi
    install -d -o mysql -g mysql "$DB_RUN"
    rm -f "$DB_SOCKET" "$DB_RUN/mariadbd.pid"
    # not forking: $! is mariadbd itself. Native AIO is often missing in containers.
    setsid /usr/sbin/mariadbd --no-defaults --user=mysql --datadir="$DB_DATA" \
        --tmpdir="$DB_RUN" --socket="$DB_SOCKET" --pid-file="$DB_RUN/mariadbd.pid" \
        --bind-address=127.0.0.1 --port="$DB_PORT" --skip-name-resolve \
        --log-error="$LOGS/mariadbd.log" --innodb-use-native-aio=0 \
        --innodb-buffer-pool-size=128M --innodb-lock-wait-timeout=900 \
        </dev/null >>"$LOGS/mariadbd.log" 2>&1 &
    echo $! >"$PIDS/mariadbd.pid"
    until_ok -d mariadbd "mariadbd" db -e 'SELECT 1' || fail "mariadbd did not come up"
    db <<EOF
CREATE DATABASE IF NOT EXISTS slurm_acct_db;
CREATE USER IF NOT EXISTS 'slurm'@'127.0.0.1' IDENTIFIED BY '$DB_PASS';
GRANT ALL ON slurm_acct_db.* TO 'slurm'@'127.0.0.1';
EOF
}

start_slurmdbd() {
    running slurmdbd >/dev/null && return
    rm -f "$DIR/slurmdbd.pid"
    /usr/sbin/slurmdbd
    record slurmdbd "$DIR/slurmdbd.pid"
    until_ok -d slurmdbd "slurmdbd" sacctmgr -n list cluster || fail "slurmdbd does not answer"
    # the cluster, the account and root's association (AccountingStorageEnforce checks -A)
    [[ -n $(sacctmgr -n -P list cluster "$CLUSTER" format=cluster) ]] ||
        sacctmgr -i add cluster "$CLUSTER" >/dev/null
    [[ -n $(sacctmgr -n -P list account "$ACCOUNT" format=account) ]] ||
        sacctmgr -i add account "$ACCOUNT" cluster="$CLUSTER" description=abglib-ci \
            organization=abglib >/dev/null
    [[ -n $(sacctmgr -n -P list assoc cluster="$CLUSTER" account="$ACCOUNT" user=root format=user) ]] ||
        sacctmgr -i add user root account="$ACCOUNT" cluster="$CLUSTER" >/dev/null
}

start_slurmctld() {
    running slurmctld >/dev/null && return
    rm -f "$DIR/slurmctld/slurmctld.pid"
    /usr/sbin/slurmctld -f "$SLURM_CONF"
    record slurmctld "$DIR/slurmctld/slurmctld.pid"
    until_ok -d slurmctld "slurmctld" scontrol ping || fail "slurmctld does not answer"
}

start_slurmd() {
    running slurmd >/dev/null && return
    rm -f "$DIR/slurmd/slurmd.pid"
    /usr/sbin/slurmd -f "$SLURM_CONF" -N "$NODE"
    record slurmd "$DIR/slurmd/slurmd.pid"
}

node_idle() { [[ $(sinfo -h -n "$NODE" -o %T 2>/dev/null) == idle* ]]; }

# abglib_cluster_of LINK -> the state directory of the cluster this script made that LINK
# points to (a symlink to <dir>/etc/slurm.conf whose first line is this script's header and
# whose ClusterName is ours); fails for anything else, a real file or another SLURM's config
abglib_cluster_of() {
    local target
    [[ -L $1 && -f $1 ]] || return 1
    target=$(readlink "$1")
    [[ $target == /*/etc/slurm.conf ]] || return 1
    [[ $(head -1 "$target") == "# written by tools/slurm-cluster.sh"* ]] || return 1
    grep -qx "ClusterName=$CLUSTER" "$target" || return 1
    echo "${target%/etc/slurm.conf}"
}

# live_daemons DIR -> the names of the daemons recorded in DIR/pid that still run; fails if none
live_daemons() {
    local name live=() PIDS=$1/pid
    for name in "${DAEMONS[@]}"; do
        running "$name" >/dev/null && live+=("$name")
    done
    ((${#live[@]})) || return 1
    echo "${live[*]}"
}

# link_default_conf -> point $DEFAULT_CONF at this cluster's slurm.conf: kept if it already
# does, replaced if it is the dangling or stale link of an earlier cluster of this script's,
# refused for anything else (another SLURM's configuration is never touched)
link_default_conf() {
    local other live
    if [[ -L $DEFAULT_CONF && $(readlink "$DEFAULT_CONF") == "$SLURM_CONF" ]]; then
        :
    elif [[ -L $DEFAULT_CONF && ! -e $DEFAULT_CONF && $(readlink "$DEFAULT_CONF") == */etc/slurm.conf ]]; then
        say "replacing the dangling $DEFAULT_CONF of a cluster whose directory is gone"
        ln -sfn "$SLURM_CONF" "$DEFAULT_CONF"
    elif other=$(abglib_cluster_of "$DEFAULT_CONF"); then
        # the symlink of an earlier cluster of this script's, in another directory, whose run
        # was killed before its `stop` (a session or CI job ended mid-test leaves exactly this)
        if live=$(live_daemons "$other"); then
            if [[ ${CI:-} == true ]]; then
                say "stopping the earlier abglib cluster in $other (still running: $live)"
                ABGLIB_SLURM_DIR=$other bash "${BASH_SOURCE[0]}" stop
            else
                fail "an earlier abglib cluster in $other is still running ($live): stop it" \
                    "first with ABGLIB_SLURM_DIR=$other $0 stop"
            fi
        else
            say "replacing the stale $DEFAULT_CONF of an earlier abglib cluster in $other" \
                "(none of its daemons runs)"
        fi
        ln -sfn "$SLURM_CONF" "$DEFAULT_CONF"
    elif [[ -e $DEFAULT_CONF || -L $DEFAULT_CONF ]]; then
        fail "$DEFAULT_CONF exists and is not this cluster's: another SLURM is configured here"
    else
        mkdir -p "$(dirname "$DEFAULT_CONF")"
        ln -s "$SLURM_CONF" "$DEFAULT_CONF"
    fi
}

do_start() {
    [[ $(id -u) == 0 ]] || fail "run me as root (the daemons and the jobs run as root)"
    do_install
    mkdir -p "$DIR" "$ETC" "$PIDS" "$LOGS" "$DIR/slurmctld" "$DIR/slurmd"
    chmod 755 "$DIR"
    write_configs
    link_default_conf
    start_munged
    start_mariadbd
    start_slurmdbd
    start_slurmctld
    start_slurmd
    if ! until_ok "node $NODE idle" node_idle; then
        # a node left down by an earlier run comes back with resume
        scontrol update nodename="$NODE" state=resume 2>/dev/null || true
        until_ok "node $NODE idle" node_idle || fail "node not idle: $(sinfo -N 2>&1)"
    fi
    sinfo
}

do_stop() {
    local i name pid deadline jobs
    # jobs first: their slurmstepd processes are not children of slurmd and would outlive it
    if running slurmctld >/dev/null; then
        jobs=$(squeue -h -o %i 2>/dev/null || true)
        if [[ -n $jobs ]]; then
            say "cancelling jobs $(echo $jobs)"
            # shellcheck disable=SC2086 # one argument per job id
            scancel --full $jobs 2>/dev/null || true
            until_ok "jobs gone" test -z "$(squeue -h -o %i 2>/dev/null)" || true
        fi
    fi
    for ((i = ${#DAEMONS[@]} - 1; i >= 0; i--)); do
        name=${DAEMONS[i]}
        if pid=$(running "$name"); then
            kill -TERM "$pid"
            deadline=$((SECONDS + TIMEOUT))
            while running "$name" >/dev/null && ((SECONDS < deadline)); do sleep 0.2; done
            if running "$name" >/dev/null; then
                say "$name ($pid) ignored SIGTERM for ${TIMEOUT}s: SIGKILL"
                kill -KILL "$pid" 2>/dev/null || true
            fi
            say "stopped $name ($pid)"
        fi
        rm -f "$PIDS/$name.pid"
    done
    if [[ -L $DEFAULT_CONF && $(readlink "$DEFAULT_CONF") == "$SLURM_CONF" ]]; then
        rm -f "$DEFAULT_CONF"
    fi
}

do_status() {
    local name pid down=0
    echo "state directory: $DIR"
    for name in "${DAEMONS[@]}"; do
        if pid=$(running "$name"); then
            printf '%-10s running, pid %s\n' "$name" "$pid"
        else
            printf '%-10s not running\n' "$name"
            down=1
        fi
    done
    ((down)) && return 1
    sinfo -N
    sacctmgr -n -P list assoc format=cluster,account,user
    squeue
}

case ${1:-} in
install) do_install ;;
link) link_default_conf ;;
start) do_start ;;
stop) do_stop ;;
status) do_status ;;
*)
    echo "usage: $0 install|start|status|stop|link" >&2
    exit 2
    ;;
esac
