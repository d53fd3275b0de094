// The log panel: a read-only text view with one timestamped line per event (loads, timings,
// errors), so messages shown once in a dialog stay readable afterwards.
#pragma once

#include <QPlainTextEdit>

namespace hlod::widgets {

class LogView : public QPlainTextEdit {
    Q_OBJECT
public:
    enum class Level { Info, Warning, Error };

    explicit LogView(QWidget* parent = nullptr);

    void info(const QString& message) { append(Level::Info, message); }
    void warning(const QString& message) { append(Level::Warning, message); }
    void error(const QString& message) { append(Level::Error, message); }
    void append(Level level, const QString& message);

    int errorCount() const { return errors_; }

Q_SIGNALS:
    void errorLogged(const QString& message);

private:
    int errors_ = 0;
};

} // namespace hlod::widgets
