// The "Open Recent" list kept in QSettings (see RecentScenes.h).
#include "RecentScenes.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSettings>
#include <QVariant>

namespace {
const char* const kKey = "recentScenes";
}

RecentScenes::RecentScenes() {
    const QVariantList stored = QSettings().value(kKey).toList();
    for (const QVariant& value : stored) {
        const QStringList files = value.toStringList();
        if (!files.isEmpty() && QFileInfo::exists(files.front())) entries_.push_back(files);
        if (entries_.size() == kMaxEntries) break;
    }
}

void RecentScenes::add(const QStringList& files) {
    if (files.isEmpty()) return;
    entries_.removeAll(files);
    entries_.prepend(files);
    while (entries_.size() > kMaxEntries)
        entries_.removeLast();
    save();
}

void RecentScenes::clear() {
    entries_.clear();
    save();
}

QString RecentScenes::label(const QStringList& files) {
    if (files.isEmpty()) return {};
    const QString first = QFileInfo(files.front()).fileName();
    if (files.size() == 1) return first;
    const int more = static_cast<int>(files.size() - 1);
    return QCoreApplication::translate("RecentScenes", "%1 + %n more", nullptr, more).arg(first);
}

void RecentScenes::save() const {
    QVariantList stored;
    for (const QStringList& files : entries_)
        stored.push_back(files);
    QSettings().setValue(kKey, stored);
}
