#pragma once
// How many CPUs this process may use: what `--threads 0` means. Not the
// machine's core count: a one-CPU Slurm task on a 64-core node, a container
// with a CPU quota or a `taskset -c 0` run must not start 64 threads that
// then fight over one CPU. The budget is the smaller of the scheduler
// affinity mask (sched_getaffinity: taskset, Slurm's task/affinity, cpusets)
// and the CFS bandwidth quota of the process's cgroup and its ancestors
// (cgroup v2 `cpu.max`, v1 `cpu.cfs_quota_us` / `cpu.cfs_period_us`),
// rounded up: a quota of 1.5 CPUs gives 2 threads.
#include <filesystem>
#include <optional>
#include <string_view>

namespace umbra::util {

/// The CPUs this process may use, at least 1; computed once and cached (the
/// mask and the quota do not change while umbra runs).
unsigned usable_cpus();

/// `threads` as given, or usable_cpus() for 0: the one place `--threads 0`
/// is resolved.
unsigned resolve_threads(unsigned threads);

/// The CPUs in this thread's affinity mask (sched_getaffinity), at least 1;
/// std::thread::hardware_concurrency() when the mask cannot be read.
unsigned affinity_cpus();

/// The tightest CFS quota, in CPUs (quota / period), over the process's CPU
/// cgroup and its ancestors up to the hierarchy's mount point; nullopt when
/// none is set ("max", -1) or nothing can be read. `mountinfo` and
/// `proc_cgroup` are the texts of /proc/self/mountinfo and /proc/self/cgroup;
/// `root` is prepended to every mount point (tests use a fake tree; "/" on a
/// real system). Malformed lines and unreadable files are skipped, never
/// thrown: a missing quota means no limit.
std::optional<double> cgroup_cpu_quota(std::string_view mountinfo, std::string_view proc_cgroup,
                                       const std::filesystem::path& root);

}  // namespace umbra::util
