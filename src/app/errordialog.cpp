#include "errordialog.h"

#include <QMessageBox>

namespace lr {

namespace {
ErrorPresenter& presenter() {
    static ErrorPresenter p;
    return p;
}
} // namespace

void setErrorPresenter(ErrorPresenter p) {
    presenter() = std::move(p);
}

void showError(QWidget* parent, const ErrorReport& report) {
    if (presenter()) {
        presenter()(report);
        return;
    }
    QMessageBox box(QMessageBox::Warning, report.title, report.summary, QMessageBox::Ok, parent);
    box.setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    if (!report.details.isEmpty()) {
        // The first few lines in the box itself, all of them in the (copyable) details.
        const int shown = std::min<int>(int(report.details.size()), 8);
        QString info = report.details.mid(0, shown).join(QLatin1Char('\n'));
        if (shown < report.details.size())
            info += QLatin1Char('\n') +
                    QObject::tr("… and %1 more (Show Details)").arg(report.details.size() - shown);
        box.setInformativeText(info);
        box.setDetailedText(report.details.join(QLatin1Char('\n')));
    }
    box.exec();
}

} // namespace lr
