#pragma once
// Internal to ThreeMfReader: ownership of lib3mf 1.8 C-interface instances and error reporting.
//
//   Lib3mfHandle   — releases the instance it holds (lib3mf_release) when destroyed; move-only.
//   Lib3mfCaller   — runs a lib3mf call and turns a failure into InputError
//                    "<file>: cannot read 3MF (<step>): <lib3mf's message>".
// Include only from .cpp files: lib3mf's headers bring Windows-style type names and macros.
#include <Model/COM/NMR_DLLInterfaces.h>

#include <string>
#include <string_view>
#include <utility>

#include "common/Error.h"
#include "mesh/formats/MessageText.h"

namespace mixengine {

class Lib3mfHandle {
  public:
    Lib3mfHandle() = default;
    Lib3mfHandle(const Lib3mfHandle&) = delete;
    Lib3mfHandle& operator=(const Lib3mfHandle&) = delete;
    Lib3mfHandle(Lib3mfHandle&& other) noexcept : instance_(std::exchange(other.instance_, nullptr)) {}
    Lib3mfHandle& operator=(Lib3mfHandle&& other) noexcept {
        std::swap(instance_, other.instance_);
        return *this;
    }
    ~Lib3mfHandle() { reset(); }

    NMR::PLib3MFBase* get() const { return instance_; }
    /// Releases the current instance and returns the slot for a lib3mf out-parameter.
    NMR::PLib3MFBase** out() {
        reset();
        return &instance_;
    }

  private:
    void reset() {
        if (instance_ != nullptr) {
            NMR::lib3mf_release(instance_);
            instance_ = nullptr;
        }
    }

    NMR::PLib3MFBase* instance_ = nullptr;
};

class Lib3mfCaller {
  public:
    explicit Lib3mfCaller(std::string label) : label_(std::move(label)) {}

    /// Throws InputError when `result` is a failure; `instance` is asked for the error message and
    /// `step` (may be empty) says what was being read.
    void check(LIB3MFRESULT result, NMR::PLib3MFBase* instance, std::string_view step) const {
        if (result == 0) {
            return;
        }
        DWORD code = 0;
        LPCSTR message = nullptr;
        std::string detail = "lib3mf error " + std::to_string(result);
        if (instance != nullptr && NMR::lib3mf_getlasterror(instance, &code, &message) == 0 &&
            message != nullptr && *message != '\0') {
            detail = oneLine(message);
        }
        const std::string where = step.empty() ? "" : " (" + std::string(step) + ")";
        throw InputError(label_ + ": cannot read 3MF" + where + ": " + detail);
    }

    const std::string& label() const { return label_; }

  private:
    std::string label_;
};

}  // namespace mixengine
