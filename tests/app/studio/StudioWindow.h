// The editor's main window for tests: a MainWindow shown on the test's X display with settings
// of its own (no recent files or layout of the user's), plus what a person does with it that
// a test cannot do by a plain call: answer the message boxes and file dialogs it opens, wait
// for builds and loads.
#pragma once

#include <functional>
#include <memory>

#include <QString>
#include <QStringList>

#include "MainWindow.h"

class QDialog;

namespace hlod::studio::test {

// Shows a fresh MainWindow (1280x800) after clearing the test settings.
std::unique_ptr<MainWindow> openWindow();

// Waits (processing events) until `done` or `ms` pass; returns done().
bool waitUntil(const std::function<bool()>& done, int ms = 120000);

// Answers the next modal dialogs as they open: `answer` gets each and returns true when it
// handled it (clicked a button, accepted); the texts of message boxes are collected.
class DialogAnswerer {
public:
    explicit DialogAnswerer(std::function<bool(QDialog*)> answer);
    ~DialogAnswerer();
    // Texts of the message boxes answered so far.
    const QStringList& messages() const { return *messages_; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::shared_ptr<QStringList> messages_;
};

// `answer` for message boxes: clicks the button with `role` ("Yes", "Ok", ...).
std::function<bool(QDialog*)> clickButton(int standardButton);

// The window shows the shown branch's build up to date: no run going on, the shown Bake node up
// to date in the document's graph and its output the shown build (no rerun pending).
bool settled(const MainWindow& window);
// Waits (two minutes at most) until settled().
bool waitSettled(const MainWindow& window);

// Opens the embedded sample scene in `window` (waiting for it) and sets the default Bake node to
// bake without the disk cache on two threads, as an undoable edit each; false when the scene
// did not load or an edit was refused.
bool openSampleWithoutCache(MainWindow& window);

// Writes a project over the embedded sample scene with the given edits to `path`: volume
// AABB, k = 2, proxies without the disk cache on two threads, instance 3 excluded.
void writeSampleProject(const QString& path);

} // namespace hlod::studio::test
