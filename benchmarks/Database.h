// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: a small wrapper of SQLite for the campaign database (the merge lives in Database.cpp). */
#ifndef MHPLAN_BENCH_DATABASE_H
#define MHPLAN_BENCH_DATABASE_H

#include <string>

struct sqlite3;
struct sqlite3_stmt;

namespace mhplan::bench::detail
{
    /** Refuse (InputError naming the file) a campaign database that exists but that no merge could use:
        not a regular file, not an SQLite database, or damaged (SQLite's quick_check; e.g. truncated). An
        absent file is fine (the merge creates it). Checked before any run. */
    void checkDatabaseFile(const std::string &file);

    /** An open SQLite database (foreign keys on, a 10 s busy timeout). Errors throw std::runtime_error. */
    class Database
    {
      public:
        explicit Database(const std::string &file);
        ~Database();
        Database(const Database &) = delete;
        Database &operator=(const Database &) = delete;

        sqlite3 *handle() { return db_; }
        void exec(const std::string &sql);
        bool hasTable(const std::string &name);

        /** A prepared statement. */
        class Statement
        {
          public:
            Statement(Database &db, const std::string &sql);
            ~Statement();
            Statement(const Statement &) = delete;
            Statement &operator=(const Statement &) = delete;
            void bind(int i, const std::string &v);
            void bind(int i, long long v);
            void bind(int i, double v);
            /** True while there is a row. */
            bool step();
            void reset();
            long long integer(int col);
            std::string text(int col);

          private:
            Database &db_;
            sqlite3_stmt *st_{nullptr};
        };

      private:
        sqlite3 *db_{nullptr};
    };
} // namespace mhplan::bench::detail

#endif
