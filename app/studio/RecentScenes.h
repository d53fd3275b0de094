// The "Open Recent" list: the last scenes opened, newest first, kept in QSettings.
//
// An entry is a list of paths because several files can form one scene (the OCCT kitchen is
// eight BREP files); reopening an entry opens them together again.
#pragma once

#include <QList>
#include <QString>
#include <QStringList>

class RecentScenes {
public:
    static constexpr int kMaxEntries = 8;

    // Reads the stored list; entries whose first path no longer exists are dropped.
    RecentScenes();

    const QList<QStringList>& entries() const { return entries_; }
    // Moves `files` to the front (adding it if new), trims to kMaxEntries and saves.
    void add(const QStringList& files);
    void clear();

    // Menu text for an entry: "room.glb", or "Room.brep + 7 more" for several files.
    static QString label(const QStringList& files);

private:
    void save() const;

    QList<QStringList> entries_;
};
