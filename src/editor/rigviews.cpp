#include "editor/rigviews.h"

#include <QSet>
#include <algorithm>

namespace lr {

std::unique_ptr<ChangeRigViews> ChangeRigViews::create(Document* document, std::vector<RigView> views,
                                                       const QString& text, QString* error) {
    QString reason;
    QSet<QString> names;
    if (views.size() > size_t(kMaxRigViews))
        reason = QObject::tr("a rig holds at most %1 saved views").arg(kMaxRigViews);
    for (const RigView& v : views) {
        if (!reason.isEmpty()) break;
        if (v.name.trimmed().isEmpty())
            reason = QObject::tr("a saved view needs a name");
        else if (v.name.size() > kMaxRigNameLength)
            reason = QObject::tr("a view's name has at most %1 characters").arg(kMaxRigNameLength);
        else if (names.contains(v.name))
            reason = QObject::tr("two saved views are called “%1”").arg(v.name);
        names.insert(v.name);
    }
    if (!reason.isEmpty()) {
        if (error) *error = reason;
        return nullptr;
    }
    return std::unique_ptr<ChangeRigViews>(new ChangeRigViews(document, std::move(views), text));
}

ChangeRigViews::ChangeRigViews(Document* document, std::vector<RigView> views, const QString& text)
    : RigCommand(document), m_before(document->rig().views), m_after(std::move(views)) {
    setText(text);
}

void ChangeRigViews::apply(const std::vector<RigView>& views) {
    Rig rig = document()->rig();
    rig.views = views;
    resetRig(rig, document()->lightIds()); // the same ids: selection and solo stay
}

void ChangeRigViews::undo() {
    apply(m_before);
}

void ChangeRigViews::redo() {
    apply(m_after);
}

bool saveRigView(Document* document, const RigView& view, QString* error) {
    std::vector<RigView> views = document->rig().views;
    auto same =
        std::find_if(views.begin(), views.end(), [&](const RigView& v) { return v.name == view.name; });
    if (same != views.end())
        *same = view;
    else
        views.push_back(view);
    auto cmd = ChangeRigViews::create(document, std::move(views),
                                      QObject::tr("Save view “%1”").arg(view.name), error);
    if (!cmd) return false;
    document->undoStack()->push(cmd.release());
    return true;
}

bool removeRigView(Document* document, const QString& name, QString* error) {
    std::vector<RigView> views = document->rig().views;
    const auto gone =
        std::remove_if(views.begin(), views.end(), [&](const RigView& v) { return v.name == name; });
    if (gone == views.end()) {
        if (error) *error = QObject::tr("no saved view is called “%1”").arg(name);
        return false;
    }
    views.erase(gone, views.end());
    auto cmd =
        ChangeRigViews::create(document, std::move(views), QObject::tr("Remove view “%1”").arg(name), error);
    if (!cmd) return false;
    document->undoStack()->push(cmd.release());
    return true;
}

} // namespace lr
