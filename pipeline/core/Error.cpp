#include "pipeline/core/Error.h"

namespace hlod {

const char* toString(ErrorCode code) {
    switch (code) {
    case ErrorCode::FileNotFound:
        return "file not found";
    case ErrorCode::FileUnreadable:
        return "file unreadable";
    case ErrorCode::UnknownFormat:
        return "unknown format";
    case ErrorCode::EmptyFile:
        return "empty file";
    case ErrorCode::Malformed:
        return "malformed";
    case ErrorCode::TooLarge:
        return "too large";
    case ErrorCode::UnsafePath:
        return "unsafe path";
    case ErrorCode::NoGeometry:
        return "no geometry";
    case ErrorCode::InvalidArgument:
        return "invalid argument";
    case ErrorCode::Cancelled:
        return "cancelled";
    case ErrorCode::Io:
        return "i/o error";
    }
    return "error";
}

namespace {
std::string oneLine(std::string s) {
    for (char& c : s) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    while (!s.empty() && s.back() == ' ')
        s.pop_back();
    return s;
}
} // namespace

Error::Error(ErrorCode code, const std::filesystem::path& file, const std::string& problem)
    : std::runtime_error(oneLine(file.string() + ": " + problem)), code_(code), file_(file),
      problem_(oneLine(problem)) {}

Error::Error(ErrorCode code, const std::string& problem)
    : std::runtime_error(oneLine(problem)), code_(code), problem_(oneLine(problem)) {}

} // namespace hlod
