// The log panel (see LogView.h).
#include "widgets/LogView.h"

#include <QFontDatabase>
#include <QTime>

namespace hlod::widgets {

LogView::LogView(QWidget* parent) : QPlainTextEdit(parent) {
    setReadOnly(true);
    setLineWrapMode(QPlainTextEdit::WidgetWidth);
    // Bounded so a long session of reloads cannot grow memory without limit.
    setMaximumBlockCount(5000);
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
}

void LogView::append(Level level, const QString& message) {
    QString tag;
    switch (level) {
    case Level::Info:
        break;
    case Level::Warning:
        tag = tr("Warning: ");
        break;
    case Level::Error:
        tag = tr("Error: ");
        ++errors_;
        break;
    }
    const QString time = QTime::currentTime().toString(QStringLiteral("HH:mm:ss"));
    appendPlainText(QStringLiteral("%1  %2%3").arg(time, tag, message));
    if (level == Level::Error) Q_EMIT errorLogged(message);
}

} // namespace hlod::widgets
