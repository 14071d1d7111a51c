#include "common/WheelGuard.h"

#include <QAbstractSpinBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QObject>
#include <QWidget>

namespace drytwin::widgets {

namespace {

/// One filter for every guarded widget, owned by the application.
class WheelOnlyWhenFocused : public QObject {
public:
    using QObject::QObject;

    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::Wheel) {
            auto* widget = qobject_cast<QWidget*>(watched);
            if (widget && !widget->hasFocus()) {
                // Ignored, so that QApplication hands the wheel on to the parent (the scroll area
                // or table the form sits in), and filtered, so that the value does not change.
                event->ignore();
                return true;
            }
        }
        return QObject::eventFilter(watched, event);
    }
};

WheelOnlyWhenFocused* sharedFilter() {
    static auto* filter = new WheelOnlyWhenFocused(QCoreApplication::instance());
    return filter;
}

void guard(QWidget* widget) {
    // StrongFocus: a click still focuses it (then the wheel works), but the wheel alone does not
    // (WheelFocus, the spin box's default, would focus it and change the value in one turn).
    widget->setFocusPolicy(Qt::StrongFocus);
    widget->removeEventFilter(sharedFilter()); // installed once, however often this is called
    widget->installEventFilter(sharedFilter());
}

} // namespace

void ignoreWheelUnlessFocused(QWidget* root) {
    if (!root) {
        return;
    }
    if (qobject_cast<QAbstractSpinBox*>(root) || qobject_cast<QComboBox*>(root)) {
        guard(root);
    }
    for (auto* spin : root->findChildren<QAbstractSpinBox*>()) {
        guard(spin);
    }
    for (auto* combo : root->findChildren<QComboBox*>()) {
        guard(combo);
    }
}

} // namespace drytwin::widgets
