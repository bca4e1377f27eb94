#!/usr/bin/env bash
# The Slurm array script on a real, single-node Slurm (Debian's slurm-wlm and munge) started here:
# three array tasks render shards 0/3, 1/3 and 2/3 into one folder, which must equal an unsharded
# run byte for byte and pass --verify. Skipped (exit 77) where slurm-wlm is not installed
# (MATPREDICT_SLURM_TESTS=1 bash scripts/test.sh installs it) or the test cannot start daemons.
# Then a task requeued part way (preemption) resumes, and the folder still equals the unsharded run.
# Usage: slurm_test.sh MAKE_DATASET CONFIG OUTPUT_FOLDER
set -u
binary=$(realpath "$1")
config=$(realpath "$2")
output=$3
root=$(cd "$(dirname "$0")/../.." && pwd)
for tool in slurmctld slurmd sbatch munged; do
  command -v "$tool" >/dev/null || { echo "skipped: $tool is not installed (slurm-wlm, munge)"; exit 77; }
done
[ "$(id -u)" -eq 0 ] || { echo "skipped: starting Slurm's daemons needs root"; exit 77; }
rm -rf "$output"
mkdir -p "$output/slurm/state" "$output/slurm/spool"
output=$(realpath "$output")
work=$output/slurm
host=$(hostname -s)
status=0

# munge authenticates Slurm's messages: its own daemon, on its own socket.
[ -s /etc/munge/munge.key ] || { /usr/sbin/mungekey --create >/dev/null 2>&1 || dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 2>/dev/null; }
chown munge:munge /etc/munge/munge.key 2>/dev/null; chmod 400 /etc/munge/munge.key
mkdir -p /run/munge && chown munge:munge /run/munge
mkdir -p "$work/munge" && chown munge:munge "$work/munge" && chmod 755 "$work/munge"
socket=$work/munge/munge.socket
runuser -u munge -- /usr/sbin/munged --socket="$socket" --pid-file="$work/munge/munged.pid" \
  --log-file="$work/munge/munged.log" --seed-file="$work/munge/munged.seed" \
  || { echo "skipped: munged would not start"; cat "$work/munge/munged.log" 2>/dev/null; exit 77; }

cat > "$work/slurm.conf" <<CONF
ClusterName=matpredict-test
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
SlurmctldPort=16817
SlurmdPort=16818
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
NodeName=$host CPUs=$(nproc) RealMemory=1024 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
stop() {
  [ -s "$work/slurmd.pid" ] && kill "$(cat "$work/slurmd.pid")" 2>/dev/null
  [ -s "$work/slurmctld.pid" ] && kill "$(cat "$work/slurmctld.pid")" 2>/dev/null
  [ -s "$work/munge/munged.pid" ] && kill "$(cat "$work/munge/munged.pid")" 2>/dev/null
}
trap stop EXIT
slurmctld -i || { echo "slurmctld would not start"; cat "$work/slurmctld.log"; exit 1; }
slurmd || { echo "slurmd would not start"; cat "$work/slurmd.log"; exit 1; }
for _ in $(seq 100); do
  sinfo -h -o %t 2>/dev/null | grep -q idle && break
  sleep 0.2
done
sinfo -h -o %t | grep -q idle || { echo "the node never became idle:"; sinfo; tail "$work/slurmd.log" "$work/slurmctld.log"; exit 1; }

# The array job, as the README runs it (resources cut to this node), waited for.
cd "$output"
MAKE_DATASET=$binary sbatch --wait --array=0-2 --cpus-per-task=1 --mem=200M --time=10 --chdir="$output" \
  --output="$output/task_%a.log" "$root/scripts/slurm/make_dataset_array.sbatch" "$config" "$output/sharded" \
  > "$work/sbatch.log" 2>&1 || { echo "the array job failed:"; cat "$work/sbatch.log" "$output"/task_*.log; status=1; }
"$binary" --config "$config" --output "$output/whole" >/dev/null 2>&1 || { echo "unsharded run failed"; exit 1; }
diff -r "$output/whole" "$output/sharded" || { echo "the array's shards differ from the unsharded run"; status=1; }
"$binary" --verify "$output/sharded" > "$work/verify.log" 2>&1 || { echo "--verify:"; cat "$work/verify.log"; status=1; }
for k in 0 1 2; do
  grep -q "of 10 in this shard" "$output/task_$k.log" || { echo "task $k did not render shard $k/3:"; cat "$output/task_$k.log"; status=1; }
done

# Preemption: task 1 requeued by the scheduler part way (frames slow enough, about 0.1 s each,
# for it to land mid-run) runs again and resumes; the folder ends as an uninterrupted run's.
slow=(--resolution 64 --spp 16)
"$binary" --config "$config" --output "$output/slow_whole" "${slow[@]}" >/dev/null 2>&1 || { echo "slow run failed"; exit 1; }
MAKE_DATASET=$binary sbatch --wait --array=0-2 --cpus-per-task=1 --mem=200M --time=10 --chdir="$output" \
  --output="$output/slow_%a.log" "$root/scripts/slurm/make_dataset_array.sbatch" "$config" "$output/slow_sharded" 3 \
  "${slow[@]}" > "$work/sbatch_slow.log" 2>&1 &
waiter=$!
for _ in $(seq 300); do
  grep -q "frames  20%" "$output/slow_1.log" 2>/dev/null && break
  sleep 0.05
done
job=$(grep -o "[0-9]*" "$work/sbatch_slow.log" | head -1)
scontrol requeue "${job}_1" || { echo "scontrol requeue failed"; status=1; }
wait "$waiter" || { echo "the requeued array job failed:"; cat "$work/sbatch_slow.log" "$output"/slow_*.log; status=1; }
grep -q "interrupted" "$output/slow_1.log" || { echo "task 1 was not interrupted by the requeue:"; cat "$output/slow_1.log"; status=1; }
grep -q "found [1-9][0-9]* complete" "$output/slow_1.log" || { echo "requeued task 1 did not resume:"; cat "$output/slow_1.log"; status=1; }
diff -r "$output/slow_whole" "$output/slow_sharded" || { echo "after the requeue the shards differ from the unsharded run"; status=1; }
exit $status
