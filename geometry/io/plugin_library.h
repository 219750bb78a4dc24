#pragma once
// Optional parts of the toolkit that link large libraries (VTK's file formats, VTK's OpenGL
// rendering, Cairo, OpenMesh) live in shared libraries loaded on first use, so that a command that
// never touches them does not pay for loading them: linked into every program, they made each
// start several times slower, a large share of a small mapping problem's whole run
// (docs/measurements.md, "Figures moved out of the code").
//
// A plugin `lib<name>.so` exports one extern "C" function `symbol` returning a pointer to a
// table of C++ function pointers (same compiler, same headers: the types cross unchanged, and so
// do exceptions). It is looked for, in this order, in `<folder>/../lib/` and in `<folder>`, where
// <folder> holds the file this code is linked into (the program, e.g. build/bin beside build/lib
// or an installation's bin/ beside its lib/; or libsa_geometry.so when the libraries are shared),
// then by the loader's search (the calling program's run path, which the installed package's
// config gives programs linking the static libraries, LD_LIBRARY_PATH, the system's folders).

#include <string>

namespace sa {

/// Loads lib<name>.so once per process and returns the address of `symbol` in it. Thread-safe.
/// Throws Error naming the library, what it is needed for (`purpose`), the folders tried and the
/// loader's message when the library or the symbol cannot be found, and std::bad_alloc when the
/// loader cannot map it (out of address space under a memory limit).
void* plugin_symbol(const std::string& name, const std::string& symbol, const std::string& purpose);

/// The table that `symbol` of lib<name>.so returns: `const Table* symbol()`.
template <class Table>
const Table& plugin_table(const std::string& name, const std::string& symbol,
                          const std::string& purpose) {
    using Entry = const Table* (*)();
    return *reinterpret_cast<Entry>(plugin_symbol(name, symbol, purpose))();
}

}  // namespace sa
