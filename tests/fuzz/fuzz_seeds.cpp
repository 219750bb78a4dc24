// Writes the seed corpus of every fuzz target: `fuzz_seeds FOLDER` makes FOLDER/<target>/seed-N,
// small valid files written by the project's own writers (fuzz_targets.h).
#include <filesystem>
#include <fstream>
#include <iostream>

#include "fuzz_targets.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: fuzz_seeds FOLDER\n";
        return 2;
    }
    std::size_t written = 0;
    for (const sa::fuzz::Target& target : sa::fuzz::targets()) {
        const std::filesystem::path folder = std::filesystem::path(argv[1]) / target.name;
        std::filesystem::create_directories(folder);
        int n = 0;
        for (const sa::fuzz::Bytes& seed : target.seeds()) {
            std::ofstream out(folder / ("seed-" + std::to_string(n++)), std::ios::binary);
            out.write(reinterpret_cast<const char*>(seed.data()),
                      static_cast<std::streamsize>(seed.size()));
            ++written;
        }
    }
    std::cout << "fuzz_seeds: " << written << " seeds for " << sa::fuzz::targets().size()
              << " targets in " << argv[1] << "\n";
    return 0;
}
