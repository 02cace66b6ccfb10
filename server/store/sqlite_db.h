// A small RAII layer over the SQLite C API: a connection, prepared statements, transactions.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/result.h"

struct sqlite3;
struct sqlite3_stmt;

namespace pool::store {

/// A failed SQLite call on a database that opened fine (disk full, I/O error): the message names
/// the statement and SQLite's reason.
class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One prepared statement. Binding indices start at 1, column indices at 0.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, double value);
  Statement& bind(int index, const std::string& text);
  Statement& bindBlob(int index, std::span<const std::uint8_t> bytes);
  /// Steps once: true while a row is there to read, false when done. Throws StoreError.
  bool step();
  /// Steps to the end (a statement without rows).
  void run();
  /// Ready to bind and step again.
  void reset();

  std::int64_t integer(int column) const;
  double real(int column) const;
  std::string text(int column) const;
  std::vector<std::uint8_t> blob(int column) const;

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
  std::string sql_;
};

/// One connection. Move-only.
class Database {
 public:
  /// Opens `path` read-write, creating it when `create`; read-only when `read_only`.
  static Result<Database> open(const std::string& path, bool read_only, bool create);

  Database(Database&&) noexcept;
  Database& operator=(Database&&) noexcept;
  ~Database();

  /// Runs `sql` (one or more statements without rows). Throws StoreError.
  void exec(const std::string& sql);
  /// Runs `sql`; the failure's reason, or empty.
  std::string tryExec(const std::string& sql);
  /// The first column of the first row of `sql` as an integer (0 when no row). Throws StoreError.
  std::int64_t integer(const std::string& sql);
  Statement prepare(const std::string& sql) { return Statement(db_, sql); }
  sqlite3* handle() const { return db_; }

 private:
  explicit Database(sqlite3* db) : db_(db) {}
  sqlite3* db_ = nullptr;
};

/// BEGIN IMMEDIATE in the constructor; commit() makes it durable, otherwise the destructor rolls
/// it back.
class Transaction {
 public:
  explicit Transaction(Database& db);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  Database& db_;
  bool done_ = false;
};

}  // namespace pool::store
