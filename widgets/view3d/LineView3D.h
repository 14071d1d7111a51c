#pragma once

#include <QStringList>
#include <QWidget>
#include <vtkSmartPointer.h>

class QComboBox;
class QLabel;
class QPushButton;
class QSlider;
class QTimer;
class QVTKOpenGLNativeWidget;
class vtkGenericOpenGLRenderWindow;
class vtkLookupTable;
class vtkPolyData;
class vtkRenderer;
class vtkScalarBarActor;

namespace drytwin::widgets {

class Workbench;

/// @brief The line in 3D (VTK): drying tube, conveyor and winnower drawn to scale, every parcel
/// in the line coloured by its simulated moisture or temperature, and a time slider with a play
/// button that scrubs through a batch. The time is shared with every time plot (timeChanged /
/// setTime).
class LineView3D : public QWidget {
    Q_OBJECT
public:
    /// @brief The section names drawn in the 3D view, in the window's language.
    const QStringList& sectionLabels() const { return m_sectionLabels; }
    /// @brief The colour bar's title as drawn (the quantity shown, in the window's language).
    QString colourBarTitle() const { return m_barTitle; }
    explicit LineView3D(Workbench& workbench, QWidget* parent = nullptr);
    ~LineView3D() override;
    /// @brief Shows the line at @p seconds since the batch start.
    void setTime(double seconds);
    double time() const { return m_time; }
    /// @brief Number of parcels drawn now (for tests).
    int parcelCount() const;
    /// @brief Colour range of the parcels now [min, max] in the shown quantity's unit.
    std::pair<double, double> colourRange() const;
    QSlider* slider() const { return m_slider; }

Q_SIGNALS:
    void timeChanged(double seconds);

private:
    void buildScene();
    void updateParcels();

    Workbench& m_workbench;
    QVTKOpenGLNativeWidget* m_view = nullptr;
    vtkSmartPointer<vtkGenericOpenGLRenderWindow> m_window;
    vtkSmartPointer<vtkRenderer> m_renderer;
    vtkSmartPointer<vtkPolyData> m_parcels;
    vtkSmartPointer<vtkLookupTable> m_lut;
    vtkSmartPointer<vtkScalarBarActor> m_bar;
    QStringList m_sectionLabels; ///< the 3D section names as drawn (tests read them)
    QString m_barTitle;
    QString m_cjkFont; ///< a font file with CJK glyphs, when one is installed
    /// Titles the colour bar with the quantity shown, in a font that has its glyphs.
    void setBarTitle(bool moisture);
    QComboBox* m_batch = nullptr;
    QComboBox* m_quantity = nullptr;
    QSlider* m_slider = nullptr;
    QPushButton* m_play = nullptr;
    QLabel* m_clock = nullptr;
    QTimer* m_timer = nullptr;
    double m_time = 0;
    double m_range[2] = {0, 0};
};

} // namespace drytwin::widgets
