// `--threads 0` is the CPUs the process may use (issue 25): the affinity
// mask and the cgroup CPU quota, read here from fake /proc texts and a fake
// cgroup tree, and from the real process under sched_setaffinity.
#include <tests/support/work_dir.h>
#include <umbra/util/cpu_budget.h>

#include <gtest/gtest.h>
#include <sched.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace umbra::util {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// A cgroup v2 system (the unified hierarchy at /sys/fs/cgroup), as systemd
// and Slurm's cgroup/v2 plugin lay it out.
constexpr const char* kMountinfoV2 =
    "22 1 0:21 / /sys rw,nosuid - sysfs sysfs rw\n"
    "30 22 0:26 / /sys/fs/cgroup rw,nosuid - cgroup2 cgroup2 rw,nsdelegate\n";

TEST(CgroupCpuQuota, V2TakesTheTightestQuotaUpToTheMount) {
  const fs::path root = geometry::test::work_dir("cpu_budget", "v2");
  const fs::path top = root / "sys/fs/cgroup";
  write(top / "cpu.max", "max 100000\n");
  write(top / "slurm/cpu.max", "400000 100000\n");        // 4 CPUs for the node's jobs
  write(top / "slurm/job_7/cpu.max", "150000 100000\n");  // 1.5 for the job
  write(top / "slurm/job_7/step_0/cpu.max", "max 100000\n");
  EXPECT_EQ(cgroup_cpu_quota(kMountinfoV2, "0::/slurm/job_7/step_0\n", root), 1.5);
  EXPECT_EQ(cgroup_cpu_quota(kMountinfoV2, "0::/slurm\n", root), 4.0);
}

TEST(CgroupCpuQuota, V2WithoutAQuotaIsNoLimit) {
  const fs::path root = geometry::test::work_dir("cpu_budget", "v2-max");
  write(root / "sys/fs/cgroup/user.slice/cpu.max", "max 100000\n");
  EXPECT_EQ(cgroup_cpu_quota(kMountinfoV2, "0::/user.slice\n", root), std::nullopt);
  EXPECT_EQ(cgroup_cpu_quota(kMountinfoV2, "0::/no/such/group\n", root), std::nullopt);
}

TEST(CgroupCpuQuota, V1ReadsTheCpuControllerOfAHybridSystem) {
  // Debian 12's hybrid layout: v1 controllers beside an empty unified tree,
  // the cpu controller mounted on its own or co-mounted with cpuacct.
  const std::string mountinfo =
      "30 22 0:26 / /sys/fs/cgroup/unified rw - cgroup2 cgroup2 rw\n"
      "31 22 0:27 / /sys/fs/cgroup/cpu,cpuacct rw shared:9 - cgroup cgroup rw,cpu,cpuacct\n"
      "32 22 0:28 / /sys/fs/cgroup/memory rw - cgroup cgroup rw,memory\n";
  const fs::path root = geometry::test::work_dir("cpu_budget", "v1");
  const fs::path top = root / "sys/fs/cgroup/cpu,cpuacct";
  write(top / "cpu.cfs_quota_us", "-1\n");
  write(top / "cpu.cfs_period_us", "100000\n");
  write(top / "docker/abc/cpu.cfs_quota_us", "200000\n");
  write(top / "docker/abc/cpu.cfs_period_us", "100000\n");
  const std::string cgroup = "4:memory:/docker/abc\n3:cpu,cpuacct:/docker/abc\n0::/\n";
  EXPECT_EQ(cgroup_cpu_quota(mountinfo, cgroup, root), 2.0);
  EXPECT_EQ(cgroup_cpu_quota(mountinfo, "3:cpu,cpuacct:/\n0::/\n", root), std::nullopt);
}

TEST(CgroupCpuQuota, InsideACgroupNamespaceThePathIsTheMounts) {
  // A container sees its own cgroup as the mount's root and "/" as its path.
  const std::string mountinfo =
      "40 30 0:26 /kubepods/pod1 /sys/fs/cgroup ro - cgroup2 cgroup2 rw\n";
  const fs::path root = geometry::test::work_dir("cpu_budget", "namespace");
  write(root / "sys/fs/cgroup/cpu.max", "50000 100000\n");
  EXPECT_EQ(cgroup_cpu_quota(mountinfo, "0::/\n", root), 0.5);
  EXPECT_EQ(cgroup_cpu_quota(mountinfo, "0::/kubepods/pod1\n", root), 0.5);
}

TEST(CgroupCpuQuota, MalformedTextsAreNoLimitNeverAnError) {
  const fs::path root = geometry::test::work_dir("cpu_budget", "malformed");
  write(root / "sys/fs/cgroup/g/cpu.max", "lots 100000\n");
  EXPECT_EQ(cgroup_cpu_quota(kMountinfoV2, "0::/g\n", root), std::nullopt);
  write(root / "sys/fs/cgroup/h/cpu.max", "0 100000\n");
  EXPECT_EQ(cgroup_cpu_quota(kMountinfoV2, "0::/h\n", root), std::nullopt);
  EXPECT_EQ(cgroup_cpu_quota("garbage\n - \n\n", "::::\n0:\n", root), std::nullopt);
  EXPECT_EQ(cgroup_cpu_quota("", "", root), std::nullopt);
}

TEST(CgroupCpuQuota, EscapedMountPointsAreUnescaped) {
  const std::string mountinfo = "30 22 0:26 / /srv/cg\\040v2 rw - cgroup2 cgroup2 rw\n";
  const fs::path root = geometry::test::work_dir("cpu_budget", "escaped");
  write(root / "srv/cg v2/job/cpu.max", "300000 100000\n");
  EXPECT_EQ(cgroup_cpu_quota(mountinfo, "0::/job\n", root), 3.0);
}

TEST(AffinityCpus, FollowsTheMaskOfTheCallingThread) {
  // Run in a thread of its own so the mask change cannot leak into others.
  unsigned before = 0, pinned = 0;
  std::thread([&] {
    before = affinity_cpus();
    cpu_set_t set;
    CPU_ZERO(&set);
    ASSERT_EQ(sched_getaffinity(0, sizeof set, &set), 0);
    int first = 0;
    while (!CPU_ISSET(first, &set)) ++first;
    CPU_ZERO(&set);
    CPU_SET(first, &set);
    ASSERT_EQ(sched_setaffinity(0, sizeof set, &set), 0);
    pinned = affinity_cpus();
  }).join();
  EXPECT_GE(before, 1u);
  EXPECT_EQ(pinned, 1u);
}

TEST(ResolveThreads, ZeroIsTheUsableCpusAndAnythingElseItself) {
  EXPECT_EQ(resolve_threads(0), usable_cpus());
  EXPECT_GE(usable_cpus(), 1u);
  EXPECT_LE(usable_cpus(), affinity_cpus());
  EXPECT_EQ(resolve_threads(3), 3u);
}

}  // namespace
}  // namespace umbra::util
