#include "cli/highgui_focus.hpp"

#ifdef SCANTRACE_HIGHGUI_QT
#include <QAbstractScrollArea>
#include <QApplication>
#include <QWidget>
#endif

namespace scantrace::cli {

void keep_keys_with_window() {
#ifdef SCANTRACE_HIGHGUI_QT
  if (!qApp) return;  // HighGUI is not the Qt one
  for (QWidget* w : QApplication::allWidgets())
    if (qobject_cast<QAbstractScrollArea*>(w)) w->setFocusPolicy(Qt::NoFocus);
#endif
}

}  // namespace scantrace::cli
