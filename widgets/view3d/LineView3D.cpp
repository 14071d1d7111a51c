#include "view3d/LineView3D.h"

#include "common/Units.h"
#include "common/Workbench.h"

#include <QComboBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>
#include <algorithm>
#include <cmath>
#include <vtkActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkVertexGlyphFilter.h>

namespace drytwin::widgets {

namespace {

// The line's layout [m]: the tube's diameter is the plant's (0.6 m); lengths are those of a
// typical tobacco line (a 25 m flash-drier duct, a 30 m belt, a 3 m winnower). Parcels move
// along each section at its length over its residence time.
constexpr double kTubeLength = 25.0, kTubeRadius = 0.3;
constexpr double kBeltLength = 30.0, kBeltWidth = 1.2;
constexpr double kWinnowerLength = 3.0;

vtkSmartPointer<vtkActor> boxActor(double x0, double x1, double width, double height, double z,
                                   const double rgb[3], double opacity) {
    auto box = vtkSmartPointer<vtkCubeSource>::New();
    box->SetBounds(x0, x1, -width / 2, width / 2, z, z + height);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(box->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
    actor->GetProperty()->SetOpacity(opacity);
    return actor;
}

} // namespace

LineView3D::LineView3D(Workbench& workbench, QWidget* parent) : QWidget(parent), m_workbench(workbench) {
    m_view = new QVTKOpenGLNativeWidget;
    m_window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
    m_view->setRenderWindow(m_window);
    m_renderer = vtkSmartPointer<vtkRenderer>::New();
    m_renderer->SetBackground(0.97, 0.97, 0.98);
    m_window->AddRenderer(m_renderer);
    m_batch = new QComboBox;
    m_quantity = new QComboBox;
    m_quantity->addItems({tr("moisture [% wb]"), tr("temperature [°C]")});
    m_slider = new QSlider(Qt::Horizontal);
    m_slider->setRange(0, 0);
    m_play = new QPushButton(tr("Play"));
    m_play->setCheckable(true);
    m_play->setEnabled(false); // until there are parcels (updateParcels)
    m_slider->setEnabled(false);
    m_clock = new QLabel(tr("Simulate the model to see the parcels."));
    m_timer = new QTimer(this);
    m_timer->setInterval(40); // 25 Hz: ten seconds of the batch per frame
    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Batch")));
    controls->addWidget(m_batch);
    controls->addWidget(m_quantity);
    controls->addWidget(m_play);
    controls->addWidget(m_slider, 1);
    controls->addWidget(m_clock);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_view, 1);
    layout->addLayout(controls);
    buildScene();

    connect(m_slider, &QSlider::valueChanged, this, [this](int v) {
        setTime(v);
        Q_EMIT timeChanged(v);
    });
    connect(m_play, &QPushButton::toggled, this, [this](bool on) {
        m_play->setText(on ? tr("Pause") : tr("Play"));
        on ? m_timer->start() : m_timer->stop();
    });
    connect(m_timer, &QTimer::timeout, this, [this] {
        const int next = m_slider->value() + 10;
        m_slider->setValue(next > m_slider->maximum() ? 0 : next);
    });
    connect(m_quantity, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
            &LineView3D::updateParcels);
    connect(m_batch, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
        const auto& si = m_workbench.siBatches();
        const int b = m_batch->currentIndex();
        if (b >= 0 && static_cast<std::size_t>(b) < si.size() && si[static_cast<std::size_t>(b)].rows() > 0) {
            m_slider->setRange(0, static_cast<int>(si[static_cast<std::size_t>(b)].rows()) - 1);
        }
        updateParcels();
    });
    connect(&m_workbench, &Workbench::dataChanged, this, [this] {
        m_batch->clear();
        for (const auto& b : m_workbench.siBatches()) {
            m_batch->addItem(QString::fromStdString(b.id));
        }
    });
    connect(&m_workbench, &Workbench::simulated, this, &LineView3D::updateParcels);
}

LineView3D::~LineView3D() = default;

void LineView3D::buildScene() {
    // Drying tube: a translucent cylinder along x (VTK's cylinder runs along y: turn it).
    auto cylinder = vtkSmartPointer<vtkCylinderSource>::New();
    cylinder->SetRadius(kTubeRadius);
    cylinder->SetHeight(kTubeLength);
    cylinder->SetResolution(32);
    auto turn = vtkSmartPointer<vtkTransform>::New();
    turn->Translate(kTubeLength / 2, 0, 2.0);
    turn->RotateZ(-90);
    auto moved = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
    moved->SetInputConnection(cylinder->GetOutputPort());
    moved->SetTransform(turn);
    auto tubeMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    tubeMapper->SetInputConnection(moved->GetOutputPort());
    auto tube = vtkSmartPointer<vtkActor>::New();
    tube->SetMapper(tubeMapper);
    tube->GetProperty()->SetColor(0.75, 0.78, 0.82);
    tube->GetProperty()->SetOpacity(0.25);
    m_renderer->AddActor(tube);
    const double belt[3] = {0.35, 0.35, 0.38};
    m_renderer->AddActor(boxActor(kTubeLength, kTubeLength + kBeltLength, kBeltWidth, 0.1, 0.0, belt, 1.0));
    const double winnower[3] = {0.55, 0.65, 0.75};
    m_renderer->AddActor(boxActor(kTubeLength + kBeltLength, kTubeLength + kBeltLength + kWinnowerLength, 2.0,
                                  2.0, 0.0, winnower, 0.3));

    m_parcels = vtkSmartPointer<vtkPolyData>::New();
    m_lut = vtkSmartPointer<vtkLookupTable>::New();
    m_lut->SetHueRange(0.0, 0.66); // dry (red) to wet (blue)
    m_lut->Build();
    auto glyphs = vtkSmartPointer<vtkVertexGlyphFilter>::New();
    glyphs->SetInputData(m_parcels);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(glyphs->GetOutputPort());
    mapper->SetLookupTable(m_lut);
    mapper->SetScalarModeToUsePointData();
    mapper->UseLookupTableScalarRangeOn();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetPointSize(9);
    actor->GetProperty()->SetRenderPointsAsSpheres(true);
    m_renderer->AddActor(actor);
    m_bar = vtkSmartPointer<vtkScalarBarActor>::New();
    m_bar->SetLookupTable(m_lut);
    m_bar->SetNumberOfLabels(4);
    // Plain text at the window's sizes: VTK's default is bold italic with a shadow, scaled with the
    // bar, which made the values far larger than the title above them.
    m_bar->UnconstrainedFontSizeOn();
    for (vtkTextProperty* text : {m_bar->GetTitleTextProperty(), m_bar->GetLabelTextProperty()}) {
        text->SetColor(0.1, 0.1, 0.1);
        text->BoldOff();
        text->ItalicOff();
        text->ShadowOff();
    }
    m_bar->GetTitleTextProperty()->SetFontSize(14);
    m_bar->GetLabelTextProperty()->SetFontSize(13);
    m_bar->SetWidth(0.08);
    m_bar->SetHeight(0.6);
    m_bar->SetPosition(0.02, 0.2); // left, clear of the line
    // Room between the title and the top value, which overlapped at 1280 x 800.
    m_bar->SetVerticalTitleSeparation(12);
    // No scale until there are parcels to colour: an empty line showed an invented 0–1 % wb.
    m_bar->SetVisibility(false);
    m_renderer->AddViewProp(m_bar);
    // Section names above each section, in the window's language. VTK's own font has no CJK
    // glyphs: a font file that has them is used where one is installed (fonts-wqy-zenhei).
    const struct {
        QString text;
        double x, z;
    } labels[] = {{tr("drying tube"), kTubeLength / 2, 3.2},
                  {tr("conveyor"), kTubeLength + kBeltLength / 2, 1.2},
                  {tr("winnower"), kTubeLength + kBeltLength + kWinnowerLength / 2, 2.8}};
    const auto needsCjkFont = [](const QString& t) {
        return std::any_of(t.begin(), t.end(), [](QChar c) { return c.unicode() >= 0x2E80; });
    };
    QString& cjkFont = m_cjkFont;
    for (const char* candidate : {"/usr/share/fonts/truetype/wqy/wqy-zenhei.ttc",
                                  "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc",
                                  "/usr/share/fonts/truetype/wqy/wqy-microhei.ttc"}) {
        if (QFileInfo::exists(QString::fromLatin1(candidate))) {
            cjkFont = QString::fromLatin1(candidate);
            break;
        }
    }
    for (const auto& l : labels) {
        auto text = vtkSmartPointer<vtkBillboardTextActor3D>::New();
        const bool cjk = needsCjkFont(l.text);
        const QString shown = cjk && cjkFont.isEmpty() ? QString() : l.text; // no tofu boxes
        text->SetInput(shown.toUtf8().constData());
        if (cjk && !cjkFont.isEmpty()) {
            text->GetTextProperty()->SetFontFamily(VTK_FONT_FILE);
            text->GetTextProperty()->SetFontFile(cjkFont.toUtf8().constData());
        }
        m_sectionLabels.push_back(l.text);
        text->SetPosition(l.x, 0, l.z);
        text->GetTextProperty()->SetFontSize(16);
        text->GetTextProperty()->SetColor(0.15, 0.15, 0.2);
        text->GetTextProperty()->SetJustificationToCentered();
        m_renderer->AddActor(text);
    }
    setBarTitle(true);
    auto* camera = m_renderer->GetActiveCamera();
    camera->SetFocalPoint(29, 0, 1);
    camera->SetPosition(22, -45, 28);
    camera->SetViewUp(0, 0, 1);
    m_renderer->ResetCamera(-1, 60, -3, 3, 0, 4);
    camera->Zoom(1.35);
}

void LineView3D::setTime(double seconds) {
    m_time = seconds;
    if (m_slider->value() != static_cast<int>(seconds)) {
        m_slider->blockSignals(true);
        m_slider->setValue(static_cast<int>(seconds));
        m_slider->blockSignals(false);
    }
    updateParcels();
}

int LineView3D::parcelCount() const {
    return m_parcels ? static_cast<int>(m_parcels->GetNumberOfPoints()) : 0;
}

std::pair<double, double> LineView3D::colourRange() const {
    return {m_range[0], m_range[1]};
}

void LineView3D::updateParcels() {
    const auto& si = m_workbench.siBatches();
    const auto& sim = m_workbench.latest().simulate;
    const int b = m_batch->currentIndex();
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto values = vtkSmartPointer<vtkDoubleArray>::New();
    values->SetName("value");
    if (sim && b >= 0 && static_cast<std::size_t>(b) < si.size() &&
        static_cast<std::size_t>(b) < sim->simulations.size()) {
        const auto& batch = si[static_cast<std::size_t>(b)];
        const auto& r = sim->simulations[static_cast<std::size_t>(b)];
        const auto& p = m_workbench.model().parameters;
        const double tauH = p[properties::Param::tau_HDT];
        const double tauC = p[properties::Param::tau_conv] + p[properties::Param::dtau_conv];
        const double tW = p[properties::Param::t_W];
        const double total = tauH + tauC + tW;
        const bool moisture = m_quantity->currentIndex() == 0;
        const auto n = static_cast<long>(batch.rows());
        const auto clampRow = [n](double k) {
            return static_cast<std::size_t>(std::clamp<long>(std::lround(k), 0, n - 1));
        };
        // One parcel per second of residence: the one that entered s seconds ago.
        for (double s = 0; s < total; s += 1.0) {
            const std::size_t entry = clampRow(m_time - s);
            const std::size_t leaves = clampRow(m_time - s + total); // the row whose outlet it is
            if (r.proxyXHdtDb.size() <= leaves) {
                continue;
            }
            const double in =
                moisture ? units::dryToWetPct(batch.xInDb[entry]) : units::kelvinToCelsius(batch.tInK[entry]);
            const double hdt = moisture ? units::dryToWetPct(r.proxyXHdtDb[leaves])
                                        : units::kelvinToCelsius(r.proxyTHdtK[leaves]);
            const double conv = moisture ? units::dryToWetPct(r.proxyXConvDb[leaves])
                                         : units::kelvinToCelsius(r.proxyTConvK[leaves]);
            const double out =
                moisture ? units::dryToWetPct(r.xOutDb[leaves]) : units::kelvinToCelsius(r.tOutK[leaves]);
            double x = 0, y = 0, z = 0, v = 0;
            // A little spread across the section so the parcels do not hide each other.
            const double lateral = 0.25 * std::sin(s * 2.3);
            if (s < tauH) {
                const double w = s / tauH;
                x = w * kTubeLength;
                y = lateral * kTubeRadius;
                z = 2.0 + 0.5 * std::cos(s * 1.7) * kTubeRadius;
                v = in + w * (hdt - in);
            } else if (s < tauH + tauC) {
                const double w = (s - tauH) / tauC;
                x = kTubeLength + w * kBeltLength;
                y = lateral * kBeltWidth;
                z = 0.15;
                v = hdt + w * (conv - hdt);
            } else {
                const double w = (s - tauH - tauC) / tW;
                x = kTubeLength + kBeltLength + w * kWinnowerLength;
                y = lateral;
                z = 1.0;
                v = conv + w * (out - conv);
            }
            points->InsertNextPoint(x, y, z);
            values->InsertNextValue(v);
        }
        m_clock->setText(tr("%1 s of %2").arg(static_cast<int>(m_time)).arg(n - 1));
        setBarTitle(moisture);
    }
    m_parcels->SetPoints(points);
    m_parcels->GetPointData()->SetScalars(values);
    const bool drawn = values->GetNumberOfTuples() > 0;
    if (drawn) {
        values->GetRange(m_range);
        m_lut->SetTableRange(m_range[0], m_range[1] > m_range[0] ? m_range[1] : m_range[0] + 1e-6);
    } else {
        m_clock->setText(tr("Simulate the model to see the parcels."));
        m_play->setChecked(false);
    }
    // Nothing to play or scale without parcels.
    m_bar->SetVisibility(drawn);
    m_play->setEnabled(drawn);
    m_slider->setEnabled(drawn);
    m_parcels->Modified();
    // Hidden (another tab), the scene is only updated: every move of the shared time cursor
    // rendered it before, for nobody. The widget renders the updated scene when it is shown.
    if (m_view->isVisible()) {
        m_window->Render();
    }
}

void LineView3D::setBarTitle(bool moisture) {
    // The quantity's words as the chooser shows them; CJK text in a font that has its glyphs.
    m_barTitle = moisture ? tr("moisture [% wb]") : tr("temperature [°C]");
    const bool cjk =
        std::any_of(m_barTitle.begin(), m_barTitle.end(), [](QChar c) { return c.unicode() >= 0x2E80; });
    // VTK's own font draws "[" and "]" as round brackets: the bar read "moisture (% wb)" beside
    // axes that say "[% wb]" (issue #72 item 11). A system font file draws them as written.
    static const QString latinFont = [] {
        for (const char* candidate : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                      "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
                                      "/usr/share/fonts/truetype/freefont/FreeSans.ttf"}) {
            if (QFileInfo::exists(QString::fromLatin1(candidate))) {
                return QString::fromLatin1(candidate);
            }
        }
        return QString();
    }();
    const QString fontFile = cjk ? m_cjkFont : latinFont;
    if (!fontFile.isEmpty()) {
        m_bar->GetTitleTextProperty()->SetFontFamily(VTK_FONT_FILE);
        m_bar->GetTitleTextProperty()->SetFontFile(fontFile.toUtf8().constData());
    }
    const QString shown = cjk && m_cjkFont.isEmpty()
                              ? (moisture ? QStringLiteral("X [% wb]") : QStringLiteral("T [°C]"))
                              : m_barTitle; // no tofu boxes without a CJK font
    m_bar->SetTitle(shown.toUtf8().constData());
}

} // namespace drytwin::widgets
