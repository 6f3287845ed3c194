#include "io/journal.h"

#include "base/atomic_file.h"
#include "base/errors.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gearfem::io
{
  namespace
  {
    constexpr const char *magic = "gearfem-journal";
    constexpr int version       = 1;

    void put_numbers(std::ostringstream &s, const std::vector<double> &v)
    {
      s << ' ' << v.size();
      for (const double x : v)
        s << ' ' << x;
    }

    /// Parse "n x1 ... xn" from `in`; false if malformed.
    bool get_numbers(std::istringstream &in, std::vector<double> &v)
    {
      std::size_t n = 0;
      if (!(in >> n) || n > 100000000)
        return false;
      v.resize(n);
      std::string tok;
      for (std::size_t i = 0; i < n; ++i)
        {
          if (!(in >> tok))
            return false;
          char *end = nullptr;
          errno     = 0;
          v[i]      = std::strtod(tok.c_str(), &end); // reads hexadecimal floating point exactly
          if (end == tok.c_str() || *end != '\0')
            return false;
        }
      return true;
    }

    void write_all(int fd, const std::string &s, const std::filesystem::path &file)
    {
      std::size_t done = 0;
      while (done < s.size())
        {
          const ssize_t w = ::write(fd, s.data() + done, s.size() - done);
          if (w < 0)
            {
              if (errno == EINTR)
                continue;
              throw std::runtime_error("cannot append to journal " + file.string() + ": " + std::strerror(errno));
            }
          done += std::size_t(w);
        }
    }
  } // namespace

  std::string content_hash(const std::string &bytes)
  {
    std::uint64_t h = 1469598103934665603ull;
    for (const unsigned char c : bytes)
      h = (h ^ c) * 1099511628211ull;
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
  }

  void start_journal(const std::filesystem::path &file, const JournalHeader &header)
  {
    std::ostringstream s;
    s << magic << ' ' << version << ' ' << header.kind << ' ' << header.key << ' ' << header.total << '\n';
    write_file_atomically(file, s.str());
  }

  namespace
  {
    std::string format_record(const JournalRecord &r)
    {
      std::ostringstream s;
      s << std::hexfloat;
      s << "record " << r.index << '\n';
      for (const auto &[block, row] : r.rows)
        {
          s << "rows " << block;
          put_numbers(s, row);
          s << '\n';
        }
      for (const auto &[name, v] : r.data)
        {
          s << "data " << name;
          put_numbers(s, v);
          s << '\n';
        }
      for (const auto &[name, t] : r.text)
        {
          if (t.find('\n') != std::string::npos)
            throw std::logic_error("journal text with a line break");
          s << "text " << name << ' ' << t << '\n';
        }
      s << "end " << r.index << '\n';
      return s.str();
    }
  } // namespace

  void rewrite_journal(const std::filesystem::path &file, const JournalHeader &header,
                       const std::vector<JournalRecord> &records)
  {
    std::ostringstream s;
    s << magic << ' ' << version << ' ' << header.kind << ' ' << header.key << ' ' << header.total << '\n';
    for (const auto &r : records)
      s << format_record(r);
    write_file_atomically(file, s.str());
  }

  void append_journal(const std::filesystem::path &file, const JournalRecord &r)
  {
    const std::string text = format_record(r);
    const int fd = ::open(file.c_str(), O_WRONLY | O_APPEND);
    if (fd < 0)
      throw std::runtime_error("cannot open journal " + file.string() + ": " + std::strerror(errno));
    try
      {
        write_all(fd, text, file);
      }
    catch (...)
      {
        ::close(fd);
        throw;
      }
    const bool synced = ::fsync(fd) == 0;
    ::close(fd);
    if (!synced)
      throw std::runtime_error("cannot sync journal " + file.string() + ": " + std::strerror(errno));
  }

  std::vector<JournalRecord> replay_journal(const std::filesystem::path &file, JournalHeader &header)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError("journal", file.string(), "an existing journal of an interrupted run", "cannot open it");
    std::string line;
    std::size_t line_no = 1;
    auto bad = [&](const std::string &why) {
      return InputError("journal", file.string() + ":" + std::to_string(line_no), "a gearfem journal (format " +
                                                                                    std::to_string(version) + ")",
                        why);
    };
    if (!std::getline(in, line))
      throw bad("empty file");
    {
      std::istringstream h(line);
      std::string m;
      int v = 0;
      if (!(h >> m >> v >> header.kind >> header.key >> header.total) || m != magic)
        throw bad("no journal header");
      if (v != version)
        throw bad("format version " + std::to_string(v));
    }
    std::vector<JournalRecord> records;
    JournalRecord cur;
    bool open = false;
    while (std::getline(in, line))
      {
        ++line_no;
        if (in.eof() && !line.empty())
          break; // the last line has no newline: a write cut short
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "record")
          {
            cur  = JournalRecord();
            open = static_cast<bool>(s >> cur.index);
            if (!open)
              throw bad("malformed record line");
          }
        else if (!open)
          throw bad("'" + tag + "' outside a record");
        else if (tag == "rows" || tag == "data")
          {
            std::string name;
            std::vector<double> v;
            if (!(s >> name) || !get_numbers(s, v))
              throw bad("malformed " + tag + " line");
            if (tag == "rows")
              cur.rows.emplace_back(name, std::move(v));
            else
              cur.data[name] = std::move(v);
          }
        else if (tag == "text")
          {
            std::string name;
            s >> name;
            std::string rest;
            std::getline(s, rest);
            cur.text[name] = rest.empty() ? rest : rest.substr(1);
          }
        else if (tag == "end")
          {
            std::size_t i = 0;
            if (!(s >> i) || i != cur.index)
              throw bad("end of record " + std::to_string(i) + " inside record " + std::to_string(cur.index));
            records.push_back(std::move(cur));
            open = false;
          }
        else
          throw bad("unknown line '" + tag + "'");
      }
    return records;
  }
} // namespace gearfem::io
