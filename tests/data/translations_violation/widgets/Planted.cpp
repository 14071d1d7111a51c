// A planted violation for translations_complete_detects_engine_text: the engine's English reason
// put on screen as it is, which the check must refuse.
void plant(QLabel* label, const Error& e) {
    label->setText(QString::fromStdString(e.reason));
}
