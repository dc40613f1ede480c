#include "gen/mesh_io/lib3mf_handle.h"

#include <cstdio>
#include <stdexcept>

#include "Model/COM/NMR_DLLInterfaces.h"

namespace tsf::mesh_io {

Lib3mfHandle::~Lib3mfHandle() {
    if (ptr_ != nullptr) NMR::lib3mf_release(ptr_);
}

Lib3mfHandle& Lib3mfHandle::operator=(Lib3mfHandle&& other) noexcept {
    if (this != &other) {
        if (ptr_ != nullptr) NMR::lib3mf_release(ptr_);
        ptr_ = other.ptr_;
        other.ptr_ = nullptr;
    }
    return *this;
}

Lib3mfObject* Lib3mfHandle::out() {
    if (ptr_ != nullptr) {
        NMR::lib3mf_release(ptr_);
        ptr_ = nullptr;
    }
    return &ptr_;
}

std::string lib3mfErrorText(int result, Lib3mfObject object) {
    DWORD code = 0;
    LPCSTR message = nullptr;
    if (object != nullptr && NMR::lib3mf_getlasterror(object, &code, &message) != LIB3MF_OK) message = nullptr;
    char codes[64];
    std::snprintf(codes, sizeof codes, "lib3mf error 0x%x/0x%x", static_cast<unsigned>(result), static_cast<unsigned>(code));
    std::string text = (message != nullptr && *message != '\0') ? std::string(message) : std::string("unknown failure");
    return text + " (" + codes + ")";
}

void checkLib3mf(int result, Lib3mfObject object, const char* what) {
    if (result == LIB3MF_OK) return;
    throw std::runtime_error(std::string(what) + ": " + lib3mfErrorText(result, object));
}

}  // namespace tsf::mesh_io
