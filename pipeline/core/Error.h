// Typed errors of the pipeline.
//
// Contract: every pipeline function that can fail on bad input throws hlod::Error (never
// prints, never aborts). The message is one line that names the file (when there is one) and
// what is wrong, ready to show to a user as is: "<file>: <problem>".
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace hlod {

enum class ErrorCode {
    FileNotFound,    // path does not exist
    FileUnreadable,  // exists but cannot be opened/read (permissions, a folder, I/O error)
    UnknownFormat,   // extension/content not recognised by any importer
    EmptyFile,       // zero bytes
    Malformed,       // parse error, truncated data, bad JSON, out-of-range index, cycle...
    TooLarge,        // absurd element counts, refused before allocating
    UnsafePath,      // external reference escaping the scene folder
    NoGeometry,      // loads, but holds no triangles
    InvalidArgument, // a parameter out of its declared range
    Cancelled,       // the caller's cancel flag was raised
    Io,              // writing output failed
};

const char* toString(ErrorCode code);

class Error : public std::runtime_error {
public:
    Error(ErrorCode code, const std::filesystem::path& file, const std::string& problem);
    Error(ErrorCode code, const std::string& problem);

    ErrorCode code() const { return code_; }
    const std::filesystem::path& file() const { return file_; }
    const std::string& problem() const { return problem_; }

private:
    ErrorCode code_;
    std::filesystem::path file_;
    std::string problem_;
};

} // namespace hlod
