// Mesh-load benchmark (not run by ctest): writes a flat grid of about a million triangles as
// binary PLY and as OBJ, then loads each in fresh child processes, once with Glint's importer
// and once with bare Assimp::Importer::ReadFile (no steps, and Triangulate, the one Glint needs),
// and prints load time and peak memory (VmHWM, and above that of a child that loads nothing) of
// each and Glint's overhead over ReadFile(Triangulate) as ratios. usage: mesh_load_bench [FOLDER]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "geometry/mesh_import.h"
#include "../mesh_test_files.h"

namespace {

// Peak resident memory of this process [KiB], from /proc/self/status.
long peakResidentKiB() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
    return -1;
}

// CPU time of this process [s], user + system: steadier than wall time on a shared machine.
double cpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// Child: loads `file` one way ("none": not at all), prints "seconds cpuSeconds peakKiB triangles".
int runChild(const std::string& mode, const std::string& file) {
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = cpuSeconds();
    size_t triangles = 0;
    if (mode == "none") {
    } else if (mode == "glint") {
        auto imported = glint::importMesh(file);
        if (!imported) {
            std::fprintf(stderr, "%s\n", imported.error().format().c_str());
            return 1;
        }
        triangles = imported->statistics.triangleCount;
    } else {
        Assimp::Importer importer;
        const aiScene* scene = importer.ReadFile(file, mode == "assimp" ? 0u : unsigned(aiProcess_Triangulate));
        if (!scene) {
            std::fprintf(stderr, "%s\n", importer.GetErrorString());
            return 1;
        }
        for (unsigned i = 0; i < scene->mNumMeshes; ++i) triangles += scene->mMeshes[i]->mNumFaces;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%.4f %.4f %ld %zu\n", seconds, cpuSeconds() - cpuStart, peakResidentKiB(), triangles);
    return 0;
}

struct Measurement {
    double seconds = 0, cpuSeconds = 0;
    long peakKiB = 0;
    size_t triangles = 0;
};

Measurement measure(const std::string& mode, const std::string& file) {
    int pipeEnds[2];
    if (pipe(pipeEnds) != 0) return {};
    const pid_t child = fork();
    if (child == 0) {
        dup2(pipeEnds[1], STDOUT_FILENO);
        close(pipeEnds[0]);
        execl("/proc/self/exe", "mesh_load_bench", "--child", mode.c_str(), file.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    close(pipeEnds[1]);
    char buffer[256] = {};
    const ssize_t length = read(pipeEnds[0], buffer, sizeof buffer - 1);
    close(pipeEnds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    Measurement result;
    if (length <= 0 || std::sscanf(buffer, "%lf %lf %ld %zu", &result.seconds, &result.cpuSeconds, &result.peakKiB,
                                      &result.triangles) != 4)
        std::fprintf(stderr, "child %s %s failed\n", mode.c_str(), file.c_str());
    return result;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 4 && std::string(argv[1]) == "--child") return runChild(argv[2], argv[3]);
    const std::string folder = argc > 1 ? argv[1] : "mesh_load_bench_files";
    std::filesystem::create_directories(folder);
    const int n = 708;  // 2·708² = 1,002,528 triangles
    const glint::test::GridMesh grid = glint::test::makeGrid(n);
    const std::string ply = folder + "/grid_1m.ply", obj = folder + "/grid_1m.obj";
    glint::test::writePly(ply, grid, true);
    glint::test::writeObj(obj, grid);
    std::printf("%zu triangles, %zu vertices; one run each, fresh processes\n", grid.indices.size() / 3, grid.positions.size());
    const long idleKiB = measure("none", ply).peakKiB;  // the libraries, loading nothing
    std::printf("a child that loads nothing peaks at %.1f MiB; 'load MiB' is the peak above that\n", idleKiB / 1024.0);
    std::printf("%-16s %-22s %10s %10s %12s %10s\n", "file", "loader", "wall s", "CPU s", "peak MiB", "load MiB");
    for (const std::string& file : {ply, obj}) {
        const Measurement glint = measure("glint", file);
        const Measurement bare = measure("assimp", file);
        const Measurement triangulated = measure("assimp-triangulate", file);
        const std::string name = std::filesystem::path(file).filename().string();
        for (const auto& [label, m] : {std::pair{"glint importMesh", glint}, std::pair{"ReadFile(0)", bare},
                                       std::pair{"ReadFile(Triangulate)", triangulated}})
            std::printf("%-16s %-22s %10.3f %10.3f %12.1f %10.1f\n", name.c_str(), label, m.seconds, m.cpuSeconds,
                        m.peakKiB / 1024.0, (m.peakKiB - idleKiB) / 1024.0);
        std::printf("%-16s glint / ReadFile(Triangulate): wall time %.2f×, CPU time %.2f×, peak memory %.2f× "
                    "(%.2f× above the idle child)\n",
                    name.c_str(), glint.seconds / triangulated.seconds, glint.cpuSeconds / triangulated.cpuSeconds,
                    double(glint.peakKiB) / triangulated.peakKiB,
                    double(glint.peakKiB - idleKiB) / double(triangulated.peakKiB - idleKiB));
    }
    return 0;
}
