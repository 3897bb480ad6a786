// Test files: write, read and copy them in one line, with the reason when it fails.
#pragma once

#include <QByteArray>
#include <QString>

namespace lrtest {

bool writeFile(const QString& path, const QByteArray& data); // creates or truncates
QByteArray readFile(const QString& path);                    // empty when missing or unreadable
// Copies `from` over `to` and makes the copy writable by its owner (resources and test data may be
// read-only).
bool copyWritable(const QString& from, const QString& to);

} // namespace lrtest
