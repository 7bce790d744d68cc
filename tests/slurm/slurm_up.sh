#!/bin/bash
# A private single-node Slurm for the batch tests (see /work/shared/reference/slurm-test.md for
# why each line): munged, slurmctld and slurmd from DIR in one PID namespace, with their own
# ports. Prints `export SLURM_CONF=...` once the node is idle. Usage: slurm_up.sh DIR CTLD SLURMD
set -eu
D=$(realpath -m "$1"); CP=${2:-16817}; SP=${3:-16818}
mkdir -p "$D"/{munge,state,spool,log}
chmod 755 "$D" "$D/munge"
dd if=/dev/urandom of="$D/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$D/munge/munge.key"
: > "$D/plugstack.conf"
cat > "$D/slurm.conf" <<CONF
ClusterName=test
SlurmctldHost=localhost
SlurmctldPort=$CP
SlurmdPort=$SP
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$D/munge/munge.sock
StateSaveLocation=$D/state
SlurmdSpoolDir=$D/spool
SlurmctldPidFile=$D/slurmctld.pid
SlurmdPidFile=$D/slurmd.pid
SlurmctldLogFile=$D/log/slurmctld.log
SlurmdLogFile=$D/log/slurmd.log
PlugStackConfig=$D/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$D/log/jobcomp.txt
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerParameters=sched_interval=1
DependencyParameters=kill_invalid_depend
ReturnToService=2
MpiDefault=none
MailProg=/bin/true
MinJobAge=600
KillWait=2
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=1000 State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$D/slurm.conf"
cat > "$D/init.sh" <<INIT
#!/bin/bash
munged -F --key-file=$D/munge/munge.key --socket=$D/munge/munge.sock --pid-file=$D/munge/munged.pid \
  --log-file=$D/munge/munged.log --seed-file=$D/munge/munged.seed &
for i in \$(seq 50); do [ -S $D/munge/munge.sock ] && break; sleep 0.1; done
slurmctld -D -f $D/slurm.conf &
slurmd -D -f $D/slurm.conf -N localhost &
wait
INIT
chmod +x "$D/init.sh"
setsid unshare --pid --fork --kill-child --mount-proc "$D/init.sh" > "$D/log/init.out" 2>&1 < /dev/null &
echo $! > "$D/unshare.pid"
for i in $(seq 300); do
  sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)' && { echo "export SLURM_CONF=$SLURM_CONF"; exit 0; }
  sleep 0.1
done
echo "slurm did not come up; see $D/log" >&2; exit 1
