#include "garden/session/journal.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include <sys/stat.h>
#include <fcntl.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "garden/scene/json_reader.h"
#include "garden/sculpt/edit_names.h"
#include "io/checked_write.h"

namespace hg::garden {

namespace {

const char* const kHeader = "hypergarden-journal";

}  // namespace

std::uint32_t crc32(const std::string& text) {
    static const auto table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t i = 0; i < 256; ++i) {
            std::uint32_t c = i;
            for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[i] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFu;
    for (unsigned char ch : text) c = table[(c ^ ch) & 0xFFu] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

JournalRead parseJournal(const std::string& text, const std::string& name) {
    JournalRead out;
    // A journal is made with its first record: an empty file, or a header
    // cut short by a crash, holds no record yet.
    const std::string fullHeader = std::string(kHeader) + " " + std::to_string(kJournalVersion) + "\n";
    if (text.size() < fullHeader.size() && fullHeader.compare(0, text.size(), text) == 0) return out;
    const std::size_t headerEnd = text.find('\n');
    const std::string header = text.substr(0, headerEnd);
    if (header.rfind(kHeader, 0) != 0) {
        out.error = name + ": not a Hypergarden journal (it does not start with '" + kHeader + "')";
        return out;
    }
    const std::string version = header.size() > std::strlen(kHeader) ? header.substr(std::strlen(kHeader) + 1) : "";
    if (version != std::to_string(kJournalVersion)) {
        out.error = name + ": journal format version '" + version + "' is not one this program reads (it reads " +
                    std::to_string(kJournalVersion) + ")";
        return out;
    }
    if (headerEnd == std::string::npos) {
        out.goodBytes = text.size();
        return out;
    }
    std::size_t pos = headerEnd + 1;
    out.goodBytes = pos;
    std::size_t number = 0;
    while (pos < text.size()) {
        ++number;
        const std::size_t end = text.find('\n', pos);
        const auto fail = [&](const std::string& why) {
            out.damage = why;
            out.damagedRecord = number;
            out.damagedOffset = pos;
        };
        if (end == std::string::npos) {
            fail("the record is cut short (no end of line): a write was interrupted");
            return out;
        }
        const std::string line = text.substr(pos, end - pos);
        if (line.size() < 10 || line[8] != ' ') {
            fail("the record has no checksum");
            return out;
        }
        const std::string json = line.substr(9);
        const std::string crcText = line.substr(0, 8);  // outlives `stop`, which points into it
        char* stop = nullptr;
        const unsigned long crc = std::strtoul(crcText.c_str(), &stop, 16);
        if (*stop != '\0' || crc != crc32(json)) {
            fail("the record's checksum does not match its text");
            return out;
        }
        try {
            out.records.push_back(parseAction(json, "record " + std::to_string(number)));
            out.recordOffsets.push_back(pos);
        } catch (const JsonError& e) {
            fail(std::string("the record cannot be read: ") + e.what());
            return out;
        }
        pos = end + 1;
        out.goodBytes = pos;
    }
    return out;
}

JournalRead readJournal(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        JournalRead out;
        out.error = path + ": cannot read the journal: " + std::strerror(errno);
        return out;
    }
    std::ostringstream s;
    s << in.rdbuf();
    return parseJournal(s.str(), path);
}

JournalWriter::~JournalWriter() {
    if (fd_ >= 0) ::close(fd_);
}

std::string JournalWriter::open(const std::string& path, std::uint64_t truncateTo) {
    path_ = path;
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd_ < 0) return "cannot open the journal " + path + " for writing: " + std::strerror(errno);
    struct stat st {};
    if (::fstat(fd_, &st) != 0) return "cannot read the size of the journal " + path + ": " + std::strerror(errno);
    goodSize_ = static_cast<std::uint64_t>(st.st_size);
    if (truncateTo < goodSize_) {
        if (std::string why = io::truncateFile(fd_, truncateTo, io::WriteSite::Journal, path); !why.empty())
            return "cannot cut the damaged tail of the journal: " + why;
        goodSize_ = truncateTo;
    }
    return "";
}

std::string JournalWriter::append(const Action& r) {
    if (fd_ < 0) return "the journal is not open";
    if (torn_) {
        // What a failed append left is cut first: records stay whole and in order.
        if (std::string why = io::truncateFile(fd_, goodSize_, io::WriteSite::Journal, path_); !why.empty()) return why;
        torn_ = false;
    }
    const std::string json = actionJson(r);
    char crc[16];
    std::snprintf(crc, sizeof crc, "%08x ", crc32(json));
    std::string line;
    if (goodSize_ == 0) line = std::string(kHeader) + " " + std::to_string(kJournalVersion) + "\n";
    line += crc + json + "\n";
    std::string why = io::writeAll(fd_, line.data(), line.size(), io::WriteSite::Journal, path_);
    if (why.empty()) why = io::syncFile(fd_, io::WriteSite::Journal, path_);
    if (!why.empty()) {
        torn_ = true;
        // Cut now as well when the file system lets us: a reader meanwhile
        // (or a crash before the retry) sees only whole records.
        if (io::truncateFile(fd_, goodSize_, io::WriteSite::Journal, path_).empty()) torn_ = false;
        return why;
    }
    goodSize_ += line.size();
    ++written_;
    return "";
}

}  // namespace hg::garden
