// Ownership and error checks for lib3mf 1.x C API objects. Internal to
// gen/mesh_io/; keeps lib3mf's headers (which define macros such as
// LIB3MFRESULT and Windows-style typedefs) out of every other header.
//
// Every object lib3mf hands out through an output pointer (model, mesh object,
// build item, reader, writer, iterator, ...) must be released with
// lib3mf_release; Lib3mfHandle does that in its destructor.
#pragma once

#include <string>

namespace tsf::mesh_io {

/// lib3mf 1.x hands out objects as PLib3MFBase* (PLib3MFBase is void*).
using Lib3mfObject = void**;

class Lib3mfHandle {
public:
    Lib3mfHandle() = default;
    ~Lib3mfHandle();
    Lib3mfHandle(Lib3mfHandle&& other) noexcept : ptr_(other.ptr_) { other.ptr_ = nullptr; }
    Lib3mfHandle& operator=(Lib3mfHandle&& other) noexcept;
    Lib3mfHandle(const Lib3mfHandle&) = delete;
    Lib3mfHandle& operator=(const Lib3mfHandle&) = delete;

    Lib3mfObject get() const { return ptr_; }
    /// For lib3mf's output parameters: releases the current object, returns
    /// the address to receive the new one.
    Lib3mfObject* out();

private:
    Lib3mfObject ptr_ = nullptr;
};

/// lib3mf's own text for the last error on object, with the numeric codes:
/// "<message> (lib3mf error 0x...)". object may be null.
std::string lib3mfErrorText(int result, Lib3mfObject object);

/// Throws std::runtime_error("<what>: <lib3mfErrorText>") unless result is
/// LIB3MF_OK.
void checkLib3mf(int result, Lib3mfObject object, const char* what);

}  // namespace tsf::mesh_io
