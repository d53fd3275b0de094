// The distributed bake on a real Slurm cluster (issue 21): the test brings up a single-node
// cluster from Debian's packages (munged, slurmctld and slurmd with their key, socket, ports,
// state, spool, pid and log files in a temporary folder; ../shared/notes/slurm-single-node.md),
// submits the shard array and the dependent final job with scripts/slurm/, and checks the
// package is byte-identical to a plain `hlod build` (the final jobs take the lean final step,
// issue 30: --no-dlod, the plan and the shards' tiles instead of the scene). A second run cancels
// one array task while it runs (scancel), sees the final job dropped and a manual final build name
// the missing shard, resubmits that one task and a new final job, and ends identical too. The
// daemons are stopped by their process ids; any process left with this cluster's SLURM_CONF (job
// steps slurmd detached) is ended by its id too. Skipped, saying why, when slurmctld, slurmd or
// munged are not installed.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "FolderCompare.h"
#include "RunCli.h"
#include "pipeline/cluster/ClusterTreeBinary.h"
#include "pipeline/graph/Parameters.h"
#include "pipeline/proxy/ContentHash.h"
#include "pipeline/proxy/ProxyBaker.h"
#include "pipeline/proxy/ProxyCache.h"
#include "pipeline/scene/SceneBinary.h"

using hlod::test::CliResult;
using hlod::test::runCli;
using hlod::test::runProcess;
using hlod::test::ScratchDir;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

const std::string kScripts = std::string(HLOD_TEST_SOURCE_DIR) + "/../scripts/slurm/";

// The shared OCCT kitchen: 12 BREP files, 11 inner nodes cut into 4 shards that all get work.
// Sloppy proxies keep every bake in this test well under a second, so the test stays short on
// a loaded machine; the default (decimate) path across processes is CliDistributedBake's.
std::vector<std::string> sceneArgs() {
    return {std::string(HLOD_TEST_DATA_DIR) + "/scenes/occt-kitchen", "--brep-unit", "0.01",
            "--proxy", "sloppy"};
}

std::string findProgram(const std::string& name) {
    std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    path += ":/usr/sbin:/sbin:/usr/local/sbin";
    std::stringstream dirs(path);
    for (std::string dir; std::getline(dirs, dir, ':');) {
        const fs::path p = fs::path(dir) / name;
        if (!dir.empty() && ::access(p.c_str(), X_OK) == 0) return p.string();
    }
    return "";
}

int freePort() {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    int port = 0;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0 &&
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) == 0)
        port = ntohs(addr.sin_port);
    ::close(fd);
    return port;
}

std::string trim(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' '))
        s.pop_back();
    return s;
}

std::string readText(const fs::path& file) {
    std::ifstream in(file);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A single-node Slurm cluster of its own in `dir` (see the notes named at the top).
class SlurmCluster {
public:
    explicit SlurmCluster(fs::path dir) : dir_(std::move(dir)) {}
    ~SlurmCluster() { stop(); }

    // Empty when the cluster is up (the node idle), else why not.
    std::string start() {
        fs::create_directories(dir_ / "munge");
        fs::create_directories(dir_ / "munge-run");
        fs::create_directories(dir_ / "state");
        fs::create_directories(dir_ / "spool");
        ::chmod(dir_.c_str(), 0711); // munged checks every folder above its socket
        ::chmod((dir_ / "munge-run").c_str(), 0755);
        const std::string key = (dir_ / "munge/munge.key").string();
        socket_ = (dir_ / "munge-run/munge.sock").string();
        if (const auto r =
                runProcess({findProgram("mungekey"), "--create", "--keyfile=" + key}, 20);
            r.exitCode != 0)
            return "mungekey failed: " + r.err;
        munged_ = spawn({findProgram("munged"), "-F", "--key-file=" + key, "--socket=" + socket_,
                         "--pid-file=" + (dir_ / "munge-run/munged.pid").string(),
                         "--seed-file=" + (dir_ / "munge/munged.seed").string(),
                         "--log-file=" + (dir_ / "munged.log").string()},
                        dir_ / "munged.out");
        if (!waitFor(
                [&] {
                    return runProcess(
                               {"sh", "-c",
                                "munge -n -S '" + socket_ + "' | unmunge -S '" + socket_ + "'"},
                               5)
                               .exitCode == 0;
                },
                10s))
            return "munged did not come up:\n" + readText(dir_ / "munged.out") +
                   readText(dir_ / "munged.log");
        writeConfig();
        ::setenv("SLURM_CONF", conf_.c_str(), 1);
        slurmctld_ = spawn({findProgram("slurmctld"), "-D", "-f", conf_}, dir_ / "slurmctld.out");
        slurmd_ = spawn({findProgram("slurmd"), "-D", "-f", conf_, "-N", "localhost"},
                        dir_ / "slurmd.out");
        if (!waitFor(
                [&] {
                    return client({"sinfo", "-h", "-n", "localhost", "-o", "%T"}) == "idle";
                },
                30s))
            return "the node did not become idle:\n" + logs();
        return "";
    }

    // A client command's stdout, trimmed (wrapped in a timeout: with a dead daemon they hang).
    std::string client(const std::vector<std::string>& argv, CliResult* result = nullptr) {
        CliResult r = runProcess(argv, 20);
        if (result) *result = r;
        return trim(r.out);
    }

    std::string jobState(const std::string& job) {
        return client({"squeue", "-h", "-j", job, "-o", "%T"});
    }

    // Until none of `jobs` is queued or running any more.
    bool waitGone(const std::vector<std::string>& jobs, std::chrono::seconds limit) {
        return waitFor(
            [&] {
                for (const std::string& j : jobs) {
                    CliResult r;
                    const std::string out = client({"squeue", "-h", "-j", j}, &r);
                    if (r.exitCode == 0 && !out.empty()) return false;
                }
                return true;
            },
            limit);
    }

    std::string logs() const {
        std::string all;
        for (const char* f : {"slurmctld.log", "slurmd.log", "slurmctld.out", "slurmd.out"})
            all += std::string("--- ") + f + "\n" + readText(dir_ / f);
        return all;
    }

    void stop() {
        if (slurmctld_ > 0) {
            const std::string jobs = client({"squeue", "-h", "-o", "%A"});
            std::stringstream ids(jobs);
            for (std::string id; ids >> id;)
                client({"scancel", id});
        }
        for (pid_t* pid : {&slurmd_, &slurmctld_, &munged_}) {
            if (*pid <= 0) continue;
            ::kill(*pid, SIGTERM);
            if (!waitFor([&] { return ::waitpid(*pid, nullptr, WNOHANG) == *pid; }, 10s)) {
                ::kill(*pid, SIGKILL);
                ::waitpid(*pid, nullptr, 0);
            }
            *pid = -1;
        }
        endLeftovers();
        if (!conf_.empty()) ::unsetenv("SLURM_CONF");
    }

private:
    template <class Pred> static bool waitFor(Pred ready, std::chrono::milliseconds limit) {
        const auto end = std::chrono::steady_clock::now() + limit;
        while (std::chrono::steady_clock::now() < end) {
            if (ready()) return true;
            std::this_thread::sleep_for(100ms);
        }
        return ready();
    }

    // A daemon in the foreground, in its own session, output to `log`, with SLURM_CONF set.
    pid_t spawn(const std::vector<std::string>& argv, const fs::path& log) {
        const pid_t pid = ::fork();
        if (pid != 0) return pid;
        ::setsid();
        const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = ::open("/dev/null", O_RDONLY);
        ::dup2(null, 0);
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        if (!conf_.empty()) ::setenv("SLURM_CONF", conf_.c_str(), 1);
        std::vector<char*> args;
        for (const std::string& a : argv)
            args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        ::execv(args[0], args.data());
        ::_exit(127);
    }

    void writeConfig() {
        conf_ = (dir_ / "slurm.conf").string();
        int ctld = freePort(), slurmd = freePort();
        while (slurmd == ctld)
            slurmd = freePort();
        const std::string user = trim(runProcess({"id", "-un"}, 5).out);
        const std::string d = dir_.string();
        std::ofstream out(conf_);
        out << "ClusterName=hlodtest\nSlurmctldHost=localhost\n"
            << "SlurmctldPort=" << ctld << "\nSlurmdPort=" << slurmd << "\n"
            << "SlurmUser=" << user << "\nSlurmdUser=" << user << "\n"
            << "AuthType=auth/munge\nCredType=cred/munge\nAuthInfo=socket=" << socket_ << "\n"
            << "MpiDefault=none\nProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n"
            << "JobAcctGatherType=jobacct_gather/none\n"
            << "AccountingStorageType=accounting_storage/none\nJobCompType=jobcomp/none\n"
            << "SelectType=select/cons_tres\nSelectTypeParameters=CR_Core\n"
            << "SchedulerType=sched/backfill\n"
            << "SchedulerParameters=batch_sched_delay=0,sched_min_interval=0\n"
            << "SlurmdParameters=config_overrides\n"
            << "CommunicationParameters=NoCtldInAddrAny,NoInAddrAny\n"
            << "ReturnToService=2\nMailProg=/bin/true\n"
            << "StateSaveLocation=" << d << "/state\nSlurmdSpoolDir=" << d << "/spool\n"
            << "SlurmctldPidFile=" << d << "/slurmctld.pid\nSlurmdPidFile=" << d << "/slurmd.pid\n"
            << "SlurmctldLogFile=" << d << "/slurmctld.log\nSlurmdLogFile=" << d << "/slurmd.log\n"
            << "NodeName=localhost NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN\n"
            << "PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP\n";
    }

    // slurmstepd detaches from slurmd (its parent becomes pid 1): end, by process id, every
    // process whose environment names this cluster's configuration.
    void endLeftovers() {
        if (conf_.empty()) return;
        const std::string mark = "SLURM_CONF=" + conf_;
        for (const auto& e : fs::directory_iterator("/proc")) {
            const std::string name = e.path().filename().string();
            if (name.find_first_not_of("0123456789") != std::string::npos) continue;
            const pid_t pid = std::stoi(name);
            if (pid == ::getpid()) continue;
            std::ifstream env(e.path() / "environ", std::ios::binary);
            std::string entry;
            while (std::getline(env, entry, '\0')) {
                if (entry == mark) {
                    ::kill(pid, SIGKILL);
                    break;
                }
            }
        }
    }

    fs::path dir_;
    std::string socket_, conf_;
    pid_t munged_ = -1, slurmctld_ = -1, slurmd_ = -1;
};

// Whether a process other than this one has `file` open (a shard waiting at a claim keeps the
// lock file open while it polls the lock, ProxyCache.cpp).
bool openedByAnotherProcess(const fs::path& file) {
    std::error_code ec;
    for (const auto& proc : fs::directory_iterator("/proc", ec)) {
        const std::string name = proc.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos ||
            std::stoi(name) == ::getpid())
            continue;
        std::error_code fdError;
        for (const auto& fd : fs::directory_iterator(proc.path() / "fd", fdError)) {
            std::error_code linkError;
            if (fs::read_symlink(fd.path(), linkError) == file) return true;
        }
    }
    return false;
}

std::string firstField(const std::string& s) { return s.substr(0, s.find_first_of(" ;\n")); }

std::string withoutChecksum(const fs::path& file) {
    std::string bytes = hlod::test::fileBytes(file);
    bytes.resize(bytes.size() - 8);
    return bytes;
}

// The key of an inner node of shard `shard` whose children are all leaves: the first proxy
// that shard needs. Its key is its structural key (nothing below it can be dissolved).
std::uint64_t firstKeyOfShard(const fs::path& cache, int shard) {
    const fs::path plan = cache / "plan";
    const auto j = nlohmann::json::parse(readText(plan / "plan.json"));
    const hlod::ClusterTree tree =
        hlod::readClusterTreeBinary(withoutChecksum(plan / "tree.bin"), plan / "tree.bin");
    const fs::path sliceFile = plan / ("shard-" + std::to_string(shard) + ".scene");
    const hlod::Scene slice = hlod::readSceneBinary(withoutChecksum(sliceFile), sliceFile);
    const hlod::BakeParams params =
        hlod::bakeParamsFrom(hlod::paramsFromJson(hlod::NodeKind::Bake, j["bake"]));
    const std::vector<std::uint64_t> keys = hlod::structuralKeys(slice, tree, params);
    std::vector<hlod::Id> stack = j["shard_list"][shard]["roots"].get<std::vector<hlod::Id>>();
    while (!stack.empty()) {
        const hlod::Id id = stack.back();
        stack.pop_back();
        const hlod::ClusterNode& n = tree.nodes[id];
        if (n.isLeaf()) continue;
        bool bottom = true;
        for (hlod::Id c : n.children)
            bottom = bottom && tree.nodes[c].isLeaf();
        if (bottom) return keys[id];
        stack.insert(stack.end(), n.children.begin(), n.children.end());
    }
    return 0;
}

} // namespace

TEST(SlurmCluster, ShardArrayAndDependentFinalJobWriteTheSingleMachinesPackage) {
    for (const char* daemon : {"slurmctld", "slurmd", "munged", "mungekey"}) {
        if (findProgram(daemon).empty())
            GTEST_SKIP() << daemon << " is not installed (Debian: slurm-wlm, munge)";
    }
    ScratchDir tmp("hlod-slurm-");
    std::vector<std::string> plain{"build"};
    for (const std::string& a : sceneArgs())
        plain.push_back(a);
    for (const std::string& a :
         {std::string("-o"), tmp / "plain", std::string("--no-cache"), std::string("--no-dlod")})
        plain.push_back(a);
    const CliResult reference = runCli(plain, 120);
    ASSERT_EQ(reference.exitCode, 0) << reference.err;

    SlurmCluster cluster(tmp.path() / "slurm");
    const std::string why = cluster.start();
    ASSERT_EQ(why, "");
    ::setenv("HLOD", HLOD_CLI, 1);
    ::setenv("HLOD_SLURM_LOGS", (tmp.path() / "logs").c_str(), 1);
    auto jobLogs = [&] {
        std::string all;
        for (const auto& e : fs::directory_iterator(tmp.path() / "logs"))
            all += "--- " + e.path().filename().string() + "\n" + readText(e.path());
        return all + cluster.logs();
    };

    // Run 1: scripts/slurm/submit.sh plans, submits the 4-task array and the final job.
    std::vector<std::string> submit{"bash", kScripts + "submit.sh", "4", tmp / "cache1",
                                    tmp / "pkg1"};
    for (const std::string& a : sceneArgs())
        submit.push_back(a);
    // The final job without the DLOD row: the lean final step (it reads the plan and the
    // shards' tiles, not the scene).
    ::setenv("HLOD_FINAL_FLAGS", "--no-dlod", 1);
    const CliResult submitted = runProcess(submit, 120);
    ::unsetenv("HLOD_FINAL_FLAGS");
    ASSERT_EQ(submitted.exitCode, 0) << submitted.err;
    std::stringstream ids(submitted.out);
    std::string array1, final1;
    ids >> array1 >> final1;
    ASSERT_FALSE(final1.empty()) << submitted.out;
    ASSERT_TRUE(cluster.waitGone({array1, final1}, 120s)) << jobLogs();
    for (int i = 0; i < 4; ++i)
        EXPECT_TRUE(fs::exists(tmp.path() / ("cache1/plan/shard-" + std::to_string(i) + ".done")))
            << jobLogs();
    EXPECT_EQ(hlod::test::folderDifference(tmp.path() / "plain", tmp.path() / "pkg1"), "")
        << jobLogs();
    EXPECT_NE(jobLogs().find("lean final step"), std::string::npos) << jobLogs();

    // Run 2: task 1 is cancelled while it runs. It is held at its first proxy by a claim this
    // test takes on that key (ProxyCache.h), so it is surely still running when cancelled.
    std::vector<std::string> plan{"plan"};
    for (const std::string& a : sceneArgs())
        plan.push_back(a);
    for (const std::string& a :
         {std::string("--shards"), std::string("4"), std::string("--cache"), tmp / "cache2"})
        plan.push_back(a);
    ASSERT_EQ(runCli(plan, 120).exitCode, 0);
    const std::uint64_t key = firstKeyOfShard(tmp.path() / "cache2", 1);
    ASSERT_NE(key, 0u);
    auto claim = std::make_unique<hlod::ProxyCache::Claim>(
        hlod::ProxyCache(tmp.path() / "cache2").claim(key));
    ASSERT_TRUE(claim->held());
    const std::string logs = (tmp.path() / "logs").string();
    std::vector<std::string> finalArgs{"sbatch", "--parsable", "--kill-on-invalid-dep=yes",
                                       "--output=" + logs + "/final-%j.out", ""};
    finalArgs.push_back(kScripts + "hlod-final.sbatch");
    for (const std::string& a : sceneArgs())
        finalArgs.push_back(a);
    for (const std::string& a : {std::string("-o"), tmp / "pkg2", std::string("--cache"),
                                 tmp / "cache2", std::string("--no-dlod")})
        finalArgs.push_back(a);
    const std::string array2 = firstField(cluster.client(
        {"sbatch", "--parsable", "--array=0-3", "--output=" + logs + "/shard-%A_%a.out",
         kScripts + "hlod-shard.sbatch", tmp / "cache2", "4"}));
    ASSERT_FALSE(array2.empty());
    finalArgs[4] = "--dependency=afterok:" + array2;
    const std::string final2 = firstField(cluster.client(finalArgs));
    ASSERT_FALSE(final2.empty());
    // Cancelled once its hlod process waits at the claimed key: it cannot have finished.
    const std::string task = array2 + "_1";
    const fs::path lockFile = tmp.path() / "cache2" / (hlod::toHex(key) + ".lock");
    const auto until = std::chrono::steady_clock::now() + 60s;
    bool waiting = false;
    while (!waiting && std::chrono::steady_clock::now() < until) {
        waiting = cluster.jobState(task) == "RUNNING" && openedByAnotherProcess(lockFile);
        if (!waiting) std::this_thread::sleep_for(100ms);
    }
    ASSERT_TRUE(waiting) << "task 1 never waited at its claimed proxy\n" << jobLogs();
    cluster.client({"scancel", task});
    // Let go of the key once the cancelled process is gone (another shard needing the same
    // proxy would wait for it too).
    const auto gone = std::chrono::steady_clock::now() + 30s;
    while (openedByAnotherProcess(lockFile) && std::chrono::steady_clock::now() < gone)
        std::this_thread::sleep_for(100ms);
    claim.reset();
    ASSERT_TRUE(cluster.waitGone({array2, final2}, 120s)) << jobLogs();
    EXPECT_FALSE(fs::exists(tmp.path() / "cache2/plan/shard-1.done"));
    EXPECT_FALSE(fs::exists(tmp.path() / "pkg2")) << "the final job ran without shard 1";

    // The final step started by hand now names the missing shard.
    std::vector<std::string> early{"build"};
    for (const std::string& a : sceneArgs())
        early.push_back(a);
    for (const std::string& a : {std::string("-o"), tmp / "pkg2", std::string("--cache"),
                                 tmp / "cache2", std::string("--no-dlod")})
        early.push_back(a);
    const CliResult tooEarly = runCli(early, 120);
    EXPECT_EQ(tooEarly.exitCode, 1);
    EXPECT_NE(tooEarly.err.find("shard 1 of 4 has not finished (no shard-1.done)"),
              std::string::npos)
        << tooEarly.err;

    // Resubmit task 1 and a final job after it: identical again.
    const std::string array3 = firstField(cluster.client(
        {"sbatch", "--parsable", "--array=1", "--output=" + logs + "/shard-%A_%a.out",
         kScripts + "hlod-shard.sbatch", tmp / "cache2", "4"}));
    ASSERT_FALSE(array3.empty());
    finalArgs[4] = "--dependency=afterok:" + array3;
    const std::string final3 = firstField(cluster.client(finalArgs));
    ASSERT_TRUE(cluster.waitGone({array3, final3}, 120s)) << jobLogs();
    EXPECT_EQ(hlod::test::folderDifference(tmp.path() / "plain", tmp.path() / "pkg2"), "")
        << jobLogs();
    ::unsetenv("HLOD");
    ::unsetenv("HLOD_SLURM_LOGS");
}
