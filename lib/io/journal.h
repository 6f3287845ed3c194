#pragma once
// An append-only journal of finished work items, for resumable runs (`gearfem solve
// --resume`). Each record is appended with one write() and fsync()ed, so a run killed at
// any instant leaves every finished record intact; a record cut short by the kill has no
// end line and is dropped on replay. Numbers are written as hexadecimal floating point
// (exact round trip). Text format, version 1:
//
//   gearfem-journal 1 <kind> <key> <total>        header: what, input hash, items planned
//   record <index>
//   rows <block> <n>  x1 x2 ... xn                 one line per table row of the record
//   data <name> <n>   x1 ... xn                    a named numeric vector
//   text <name> <text to end of line>
//   end <index>
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace gearfem::io
{
  struct JournalRecord
  {
    std::size_t index = 0;
    /// (block name, one row) in the order written; a block may have many rows.
    std::vector<std::pair<std::string, std::vector<double>>> rows;
    std::map<std::string, std::vector<double>> data;
    std::map<std::string, std::string> text; ///< values without line breaks
  };

  struct JournalHeader
  {
    std::string kind; ///< e.g. "solve"
    std::string key;  ///< the hash of what the run depends on (input file)
    std::size_t total = 0;
  };

  /// Start a journal at `file` (replacing any), atomically: the header only.
  void start_journal(const std::filesystem::path &file, const JournalHeader &header);

  /// Replace the journal by `header` and `records`, atomically (a resumed run starts from
  /// the replayed records, without the tail a killed write may have left).
  void rewrite_journal(const std::filesystem::path &file, const JournalHeader &header,
                       const std::vector<JournalRecord> &records);

  /// Append one record (one write, then fsync). Throws std::runtime_error on I/O failure.
  void append_journal(const std::filesystem::path &file, const JournalRecord &record);

  /// Read a journal: its header and every complete record, in order. A trailing record
  /// without its end line (a killed write) is dropped. Throws InputError naming the file
  /// and line for a missing or malformed journal.
  std::vector<JournalRecord> replay_journal(const std::filesystem::path &file, JournalHeader &header);

  /// FNV-1a 64-bit hash of a byte string, as 16 hex digits.
  std::string content_hash(const std::string &bytes);
} // namespace gearfem::io
