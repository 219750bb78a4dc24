#include "geometry/io/plugin_library.h"

#include <dlfcn.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <new>
#include <vector>

#include "optim/errors.h"

namespace sa {

namespace {

/// The folder of the file that holds this code: the program when the library is linked
/// statically, libsa_geometry.so when it is a shared library.
std::filesystem::path module_folder() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&plugin_symbol), &info) != 0 && info.dli_fname != nullptr &&
        info.dli_fname[0] != '\0') {
        std::error_code error;
        const std::filesystem::path file =
            std::filesystem::canonical(std::filesystem::path(info.dli_fname), error);
        if (!error) return file.parent_path();
    }
    std::error_code error;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : exe.parent_path();
}

}  // namespace

void* plugin_symbol(const std::string& name, const std::string& symbol,
                    const std::string& purpose) {
    static std::mutex mutex;
    static std::map<std::string, void*> loaded;  // file name -> handle; never closed
    const std::string file = "lib" + name + ".so";
    std::lock_guard<std::mutex> lock(mutex);
    void*& handle = loaded[file];
    if (handle == nullptr) {
        std::string message;
        std::vector<std::string> candidates;
        const std::filesystem::path folder = module_folder();
        if (!folder.empty()) {
            candidates.push_back((folder.parent_path() / "lib" / file).string());
            candidates.push_back((folder / file).string());
        }
        candidates.push_back(file);  // the loader's own search
        for (const std::string& candidate : candidates) {
            if (candidate != file && !std::filesystem::exists(candidate)) continue;
            handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (handle != nullptr) break;
            const char* error = dlerror();
            message = error != nullptr ? error : "unknown error";
            // The loader could not map the library or one it needs: out of address space (a
            // memory limit), not a missing file.
            if (message.find("failed to map segment") != std::string::npos ||
                message.find("annot allocate memory") != std::string::npos)
                throw std::bad_alloc();
            if (candidate != file) break;  // this one exists: its error is the reason
        }
        if (handle == nullptr) {
            std::string tried;  // the folders, without the last candidate (the loader's search)
            for (std::size_t i = 0; i + 1 < candidates.size(); ++i) {
                tried += (i > 0 ? ", " : "") +
                         std::filesystem::path(candidates[i]).parent_path().string();
            }
            throw Error("cannot load " + file + ", needed for " + purpose + ": " + message +
                        " (looked in " + (tried.empty() ? "" : tried + " and ") +
                        "the loader's search path)");
        }
    }
    dlerror();
    void* address = dlsym(handle, symbol.c_str());
    if (address == nullptr) {
        const char* error = dlerror();
        throw Error(file + " has no " + symbol + " (needed for " + purpose +
                    "): " + (error != nullptr ? error : "null symbol"));
    }
    return address;
}

}  // namespace sa
