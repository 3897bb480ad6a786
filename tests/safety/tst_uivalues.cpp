// No input in any field can store NaN, Inf or an out-of-range value (issue 6, "UI values"). Hostile text is
// typed into every numeric field of the Properties dock (for lights that show each of them), the Render
// settings dock and the light table's cell editors; the rig must stay unchanged where the text is not a
// valid value, and always stay a rig the format accepts. The same values go through the model API as
// QVariants (NaN, ±Inf as doubles, numeric strings).
#include "app/lightsdock.h"
#include "app/numberedit.h"
#include "app/propertiesdock.h"
#include "app/rendersettingsdock.h"
#include "app/viewsettings.h"
#include "core/rigjson.h"
#include "editor/lighttablemodel.h"
#include "editor/rigfixture.h"

#include <QAbstractItemDelegate>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QStandardPaths>
#include <QTableView>
#include <QtTest>
#include <cmath>
#include <limits>

using namespace lr;

namespace {

// Never a valid value anywhere: not numbers, not finite, or beyond every limit of the format (1e12 at most).
const QStringList kNeverValid{QStringLiteral("nan"),    QStringLiteral("NaN"),      QStringLiteral("inf"),
                              QStringLiteral("-inf"),   QStringLiteral("Infinity"), QStringLiteral("1e999"),
                              QStringLiteral("-1e999"), QStringLiteral("1e308"),    QStringLiteral("1e13"),
                              QStringLiteral("0x10"),   QStringLiteral("1e"),       QStringLiteral("--1"),
                              QStringLiteral("1..2"),   QStringLiteral("٣")};

// A rig whose lights, between them, show every field of the Properties dock.
Rig everyFieldRig() {
    Rig rig;
    rig.name = QStringLiteral("Fields");
    Light a = makeLight(LightType::Spot, QStringLiteral("spot smooth"));
    a.temperature = 5000.0;
    a.cone = {ConeModel::Smooth, 20, 35, 2};
    a.falloff = {FalloffModel::RangePower, 10.0, 2.0, 1.0, 0.0, 0.0};
    a.ambient = glm::dvec3(0.1);
    a.gobo = GoboSpec{QStringLiteral("gobo.png"), {}, 1.0, 0.0}; // issue 39: its scale and rotation
    Light b = makeLight(LightType::Point, QStringLiteral("point polynomial"));
    b.falloff = {FalloffModel::InversePolynomial, 20.0, 2.0, 1.0, 0.5, 0.25};
    b.temperature = 3000.0;
    b.ies = IesSpec{QStringLiteral("down.ies")}; // issue 39: the profile's multiplier and rotation
    Light c = makeLight(LightType::Rim, QStringLiteral("rim"));
    Light d = makeLight(LightType::Directional, QStringLiteral("directional"));
    a.shadow.enabled = true; // issue 14: the shadow's fields (size on the spot, angle on the directional)
    d.shadow.enabled = true;
    Light e = makeLight(LightType::Rect, QStringLiteral("rect")); // issue 16: width, height, roll
    e.barnDoors = BarnDoors{}; // issue 39: the barn doors' angle and length
    Light f = makeLight(LightType::Disk, QStringLiteral("disk")); // radius
    rig.lights = {a, b, c, d, e, f};
    return rig;
}

QByteArray bytes(const Document& doc) {
    return writeRigJson(doc.rig());
}

// Typed key by key: each keystroke is validated on its own, so a valid prefix ("1e3" of "1e308") may be
// what is left when Return is pressed. Only ASCII can be typed this way.
void typeInto(QAbstractSpinBox* box, const QString& text) {
    for (QChar c : text)
        if (c.unicode() > 0x7E) return;
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
    box->clearFocus();
}

// Pasted (or dropped) as a whole over the selection: the whole text is validated at once.
void pasteInto(QAbstractSpinBox* box, const QString& text) {
    auto* line = box->findChild<QLineEdit*>();
    QVERIFY(line);
    box->setFocus();
    box->selectAll();
    line->insert(text);
    QTest::keyClick(box, Qt::Key_Return);
    box->clearFocus();
}

QString fieldName(const QWidget* w) {
    for (; w; w = w->parentWidget())
        if (!w->objectName().isEmpty() && !w->objectName().startsWith(QLatin1String("qt_")))
            return w->objectName();
    return QStringLiteral("?");
}

bool usable(QWidget* w, QWidget* top) {
    return w->isVisibleTo(top) && w->isEnabled();
}

// The text as the field would read it, or NaN when it is not a number.
double parsed(const QAbstractSpinBox* box, const QString& text) {
    bool ok = false;
    const double v = box->locale().toDouble(text, &ok);
    return ok ? v : std::numeric_limits<double>::quiet_NaN();
}

} // namespace

class TestUiValues : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void propertiesDock_everyNumberField() {
        Document doc;
        doc.newRig(everyFieldRig());
        PropertiesDock dock(&doc);
        dock.resize(400, 900);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        const QList<NumberEdit*> edits = dock.findChildren<NumberEdit*>();
        QVERIFY(edits.size() >=
                15); // temperature, intensity, position x3, direction x3, falloff x5, cone x3, ...
        QSet<NumberEdit*> tested;
        int attempts = 0;
        for (int row = 0; row < doc.lightCount(); ++row) {
            doc.setSelectedRows({row}, row);
            for (NumberEdit* edit : edits) {
                if (!usable(edit, &dock)) continue;
                tested.insert(edit);
                QStringList inputs = kNeverValid;
                inputs << QStringLiteral("-5") << QStringLiteral("1e-99999") << QStringLiteral("-0.000001")
                       << QStringLiteral("1000000.5") << QStringLiteral("91");
                for (const QString& text : inputs) {
                    const QByteArray before = bytes(doc);
                    const int steps = doc.undoStack()->count();
                    const double v = parsed(edit, text);
                    const bool couldBeValid =
                        std::isfinite(v) && edit->accepts(v) && !kNeverValid.contains(text);
                    pasteInto(edit, text);
                    ++attempts;
                    if (!couldBeValid) {
                        QVERIFY2(bytes(doc) == before,
                                 qPrintable(QStringLiteral("pasting \"%2\" into %1 changed the rig")
                                                .arg(fieldName(edit), text)));
                        QCOMPARE(doc.undoStack()->count(), steps);
                    }
                    QVERIFY(std::isfinite(edit->value()));
                    QVERIFY(edit->accepts(edit->value()));
                    QCOMPARE(validateRig(doc.rig()), QString());
                    // Typed: what is stored, if anything, is a valid prefix's value.
                    typeInto(edit, text);
                    QVERIFY(std::isfinite(edit->value()));
                    QVERIFY2(edit->accepts(edit->value()),
                             qPrintable(fieldName(edit) + QLatin1Char(' ') + text));
                    QCOMPARE(validateRig(doc.rig()), QString());
                    QVERIFY(readRigJson(bytes(doc), QStringLiteral("ui.json")).ok());
                }
            }
        }
        QCOMPARE(tested.size(), edits.size()); // every numeric field was reachable and tried
        QVERIFY(attempts > 100);
    }

    // Focusing a field and pressing Return (or leaving it) without typing stores nothing: the field shows
    // the value rounded to 7 digits, which must not be read back over the exact stored value.
    void propertiesDock_returnWithoutTyping_changesNothing() {
        Document doc;
        Rig rig = everyFieldRig();
        rig.lights[0].direction = glm::dvec3(-0.5773502691896258, -0.5773502691896258, -0.5773502691896258);
        rig.lights[0].intensity = 1.234567891234;
        rig.lights[0].position = glm::dvec3(0.1 + 0.2, 1.0 / 3.0, 2.0 / 3.0);
        doc.newRig(rig);
        PropertiesDock dock(&doc);
        dock.show();
        doc.setSelectedRows({0}, 0);
        const QByteArray before = bytes(doc);
        for (NumberEdit* edit : dock.findChildren<NumberEdit*>()) {
            if (!usable(edit, &dock)) continue;
            edit->setFocus();
            QTest::keyClick(edit, Qt::Key_Return);
            edit->clearFocus();
            QVERIFY2(bytes(doc) == before,
                     qPrintable(QStringLiteral("Return in %1 changed the rig").arg(fieldName(edit))));
        }
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void propertiesDock_nameField() {
        Document doc;
        doc.newRig(everyFieldRig());
        PropertiesDock dock(&doc);
        dock.show();
        doc.setSelectedRows({0}, 0);
        auto* name = qobject_cast<QLineEdit*>(dock.field(LightProperty::Name));
        QVERIFY(name);
        for (const QString& text : {QString(10000, QChar(u'n')), QStringLiteral("   "), QStringLiteral("\t"),
                                    QStringLiteral("\U0001F600").repeated(300)}) {
            name->setFocus();
            name->selectAll();
            name->insert(text); // pasted: keyClicks only types ASCII
            QTest::keyClick(name, Qt::Key_Return);
            QCOMPARE(validateRig(doc.rig()), QString());
            QVERIFY(!doc.light(0).name.trimmed().isEmpty());
        }
    }

    void renderSettings_shininessAndExposure() {
        Document doc;
        doc.newRig(everyFieldRig());
        ViewSettings view;
        RenderSettingsDock dock(&doc, &view);
        dock.show();
        const QList<QAbstractSpinBox*> boxes = dock.findChildren<QAbstractSpinBox*>();
        QVERIFY(!boxes.isEmpty());
        for (QAbstractSpinBox* box : boxes) {
            if (!usable(box, &dock)) continue;
            for (const QString& text : kNeverValid + QStringList{QStringLiteral("-5")}) {
                const QByteArray before = bytes(doc);
                pasteInto(box, text);
                if (auto* n = qobject_cast<NumberEdit*>(box)) {
                    const double v = parsed(n, text);
                    if (!(std::isfinite(v) && n->accepts(v) && !kNeverValid.contains(text)))
                        QCOMPARE(bytes(doc), before);
                    QVERIFY(std::isfinite(n->value()));
                } else if (auto* d = qobject_cast<QDoubleSpinBox*>(box)) {
                    QVERIFY(std::isfinite(d->value()));
                    QVERIFY(d->value() >= d->minimum() && d->value() <= d->maximum());
                }
                QCOMPARE(validateRig(doc.rig()), QString());
                typeInto(box, text);
                QCOMPARE(validateRig(doc.rig()), QString());
            }
        }
        QVERIFY(std::isfinite(view.options().exposure));
    }

    // The rig's name: an undoable edit, never longer than the format allows, shown again after undo.
    void renderSettings_rigName() {
        Document doc;
        doc.newRig(everyFieldRig());
        ViewSettings view;
        RenderSettingsDock dock(&doc, &view);
        dock.show();
        auto* name = dock.findChild<QLineEdit*>(QStringLiteral("rigName"));
        QVERIFY(name);
        QCOMPARE(name->text(), doc.rig().name);
        const QString before = doc.rig().name;
        const int steps = doc.undoStack()->count();
        name->setFocus();
        name->selectAll();
        name->insert(QStringLiteral("Studio \U0001F4A1 key"));
        QTest::keyClick(name, Qt::Key_Return);
        QCOMPARE(doc.rig().name, QStringLiteral("Studio \U0001F4A1 key"));
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        name->selectAll();
        name->insert(QString(10000, QChar(u'n'))); // pasted: the field stops at the format's limit
        QTest::keyClick(name, Qt::Key_Return);
        QVERIFY(doc.rig().name.size() <= kMaxRigNameLength);
        QCOMPARE(validateRig(doc.rig()), QString());
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(doc.rig().name, before);
        QCOMPARE(name->text(), before);
        QVERIFY(!dock.findChild<QComboBox*>(QStringLiteral("rigSpace"))->currentText().isEmpty());
    }

    // The table's cell editors hand their text to the model, which parses and validates it.
    void lightTable_cellEditors() {
        Document doc;
        doc.newRig(everyFieldRig());
        LightsDock dock(&doc);
        dock.show();
        QTableView* view = dock.view();
        QAbstractItemModel* model = view->model();
        int tried = 0;
        for (int column : {int(LightTableModel::IntensityColumn), int(LightTableModel::FalloffColumn)}) {
            for (int row = 0; row < model->rowCount(); ++row) {
                const QModelIndex index = model->index(row, column);
                if (!(model->flags(index) & Qt::ItemIsEditable)) continue;
                QAbstractItemDelegate* delegate = view->itemDelegateForIndex(index);
                for (const QString& text :
                     kNeverValid + QStringList{QStringLiteral("-5"), QStringLiteral("")}) {
                    QWidget* editor = delegate->createEditor(view->viewport(), QStyleOptionViewItem(), index);
                    QVERIFY(editor);
                    delegate->setEditorData(editor, index);
                    auto* line = qobject_cast<QLineEdit*>(editor);
                    if (!line) line = editor->findChild<QLineEdit*>();
                    QVERIFY(line);
                    line->setText(text);
                    const QByteArray before = bytes(doc);
                    delegate->setModelData(editor, model, index);
                    delete editor;
                    ++tried;
                    // "" means "no range" where the model allows it (inverse-polynomial): still a valid rig.
                    if (!text.isEmpty()) QCOMPARE(bytes(doc), before);
                    QCOMPARE(validateRig(doc.rig()), QString());
                }
            }
        }
        QVERIFY(tried > 20);
    }

    // The same through the model and document APIs, with values no text field can produce.
    void modelAndDocument_refuseNonFiniteVariants() {
        Document doc;
        doc.newRig(everyFieldRig());
        LightTableModel model(&doc);
        const double nan = std::numeric_limits<double>::quiet_NaN(),
                     inf = std::numeric_limits<double>::infinity();
        const QList<QVariant> hostile{nan,
                                      inf,
                                      -inf,
                                      -5.0,
                                      1e300,
                                      QStringLiteral("nan"),
                                      QStringLiteral("1e999"),
                                      QVariant::fromValue(glm::dvec3(nan, 0, 0)),
                                      QVariant::fromValue(glm::dvec3(0, inf, 0))};
        const QByteArray before = bytes(doc);
        for (int column : {int(LightTableModel::IntensityColumn), int(LightTableModel::FalloffColumn),
                           int(LightTableModel::ColorColumn)})
            for (int row = 0; row < model.rowCount(); ++row)
                for (const QVariant& v : hostile) {
                    model.setData(model.index(row, column), v, Qt::EditRole);
                    QCOMPARE(bytes(doc), before);
                }
        for (int p = 0; p < kLightPropertyCount; ++p) {
            const auto property = LightProperty(p);
            if (property == LightProperty::Name || property == LightProperty::Type ||
                property == LightProperty::Enabled)
                continue;
            for (const QVariant& v :
                 {QVariant(nan), QVariant(inf), QVariant(-inf), QVariant::fromValue(glm::dvec3(nan)),
                  QVariant::fromValue(glm::dvec3(0, 0, inf)), QVariant::fromValue(glm::dvec3(1e300))}) {
                QString error;
                QVERIFY(!doc.setLightValue({0, 1, 2, 3}, property, v, &error));
                QCOMPARE(bytes(doc), before);
            }
        }
        for (const RigProperty p : {RigProperty::Ambient, RigProperty::Shininess})
            for (const QVariant& v : {QVariant(nan), QVariant(inf), QVariant::fromValue(glm::dvec3(nan))}) {
                doc.setRigValue(p, v);
                QCOMPARE(bytes(doc), before);
            }
    }
};

QTEST_MAIN(TestUiValues)
#include "tst_uivalues.moc"
