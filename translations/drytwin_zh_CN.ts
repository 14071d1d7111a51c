<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>QObject</name>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="32"/>
        <source>set %1 to %2</source>
        <translation>将 %1 设为 %2</translation>
    </message>
</context>
<context>
    <name>TrainingPanel</name>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="52"/>
        <source>PI loop (the plant&apos;s own)</source>
        <translation>PI 回路（装置自带）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="54"/>
        <source>MPC on the physics model</source>
        <translation>基于物理模型的 MPC</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="56"/>
        <source>MPC on PGRL-CC</source>
        <translation>基于 PGRL-CC 的 MPC</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="58"/>
        <source>MPC on the external-input residual model</source>
        <translation>基于外部输入残差模型的 MPC</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="60"/>
        <source>MPC on the LSTM</source>
        <translation>基于 LSTM 的 MPC</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="68"/>
        <source>Tube wall heat loss</source>
        <translation>管壁散热损失</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="70"/>
        <source>Gas-phase coupling</source>
        <translation>气相耦合</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="72"/>
        <source>Heat-transfer fouling</source>
        <translation>传热结垢</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="74"/>
        <source>Moisture meter lag</source>
        <translation>水分仪滞后</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="76"/>
        <source>Moisture meter offset</source>
        <translation>水分仪偏差</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="78"/>
        <source>Transport delay error</source>
        <translation>输送延时误差</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="80"/>
        <source>Falling-rate drying</source>
        <translation>降速干燥</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="82"/>
        <source>Ambient re-absorption</source>
        <translation>环境回潮</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="84"/>
        <source>Inlet moisture gauge offset</source>
        <translation>入口水分仪零点偏移</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="86"/>
        <source>Hot-air thermocouple lag</source>
        <translation>热风热电偶滞后</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="88"/>
        <source>Inlet moisture gauge scatter</source>
        <translation>入口水分仪读数离散</translation>
    </message>
</context>
<context>
    <name>TrainingRunner</name>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="31"/>
        <location filename="../widgets/training/TrainingRunner.cpp" line="36"/>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="45"/>
        <location filename="../widgets/training/TrainingRunner.cpp" line="51"/>
        <source>Open session</source>
        <translation>打开会话</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="61"/>
        <location filename="../widgets/training/TrainingRunner.cpp" line="93"/>
        <source>Start a session first.</source>
        <translation>请先开始一个会话。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="92"/>
        <location filename="../widgets/training/TrainingRunner.cpp" line="98"/>
        <source>Save session</source>
        <translation>保存会话</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::CalibrationPanel</name>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="28"/>
        <source>Free</source>
        <translation>自由</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="28"/>
        <source>Lower</source>
        <translation>下限</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="28"/>
        <source>Upper</source>
        <translation>上限</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="28"/>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="64"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="59"/>
        <source> evaluations</source>
        <translation> 次评估</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="60"/>
        <source>Calibrate</source>
        <translation>标定</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="61"/>
        <source>Stop, keep best</source>
        <translation>停止并保留最优</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="64"/>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="64"/>
        <source>Estimate</source>
        <translation>估计值</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="64"/>
        <source>95 % interval</source>
        <translation>95 % 区间</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="64"/>
        <source>Fisher SE</source>
        <translation>Fisher 标准误</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="64"/>
        <source>At bound</source>
        <translation>触及边界</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="66"/>
        <source>Fits the free parameters to the calibration rows (every 10th kept row, the first 300) with NLopt: a global search, then BOBYQA.</source>
        <translation>用 NLopt 将自由参数拟合到标定行（保留行中每隔 10 行取一行，取前 300 行）：先全局搜索，再用 BOBYQA。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="70"/>
        <source>best loss [-]</source>
        <translation>最优损失 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="71"/>
        <source>θ / θ final [-]</source>
        <translation>θ / θ 最终值 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="72"/>
        <source>share of the evaluation budget used [-]</source>
        <translation>已用评估预算比例 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="76"/>
        <source>Free parameters and their search bounds:</source>
        <translation>自由参数及其搜索范围：</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="86"/>
        <source>X_out [% wb]</source>
        <translation>X_out [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="106"/>
        <source>best loss so far</source>
        <translation>迄今最优损失</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="154"/>
        <source>Cannot calibrate: %1</source>
        <translation>无法标定：%1</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="162"/>
        <source>Calibrating…</source>
        <translation>正在标定…</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="182"/>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="182"/>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="186"/>
        <source>%1 after %2 evaluations (%3 s). Loss %4 → %5; outlet MAE %6 → %7 % wb, %8 → %9 °C. Intervals: %10.</source>
        <translation>%1，共 %2 次评估（%3 s）。损失 %4 → %5；出口 MAE %6 → %7 % 湿基，%8 → %9 °C。区间：%10。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="211"/>
        <source>loss evaluations [-]</source>
        <translation>损失评估次数 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="212"/>
        <source>best loss</source>
        <translation>最优损失</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="244"/>
        <source>measured %1</source>
        <translation>实测 %1</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="247"/>
        <source>before</source>
        <translation>之前</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="250"/>
        <source>after</source>
        <translation>之后</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::ColumnMappingDialog</name>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="29"/>
        <source>Column mapping</source>
        <translation>列映射</translation>
    </message>
    <message>
        <source>Could not read the headers of %1.</source>
        <translation>无法读取 %1 的表头。</translation>
    </message>
    <message>
        <source>Choose, for each column DryTwin needs, the header your files use and the unit its values are in (converted when read); required columns are marked *.</source>
        <translation>为 DryTwin 需要的每一列选择您文件中使用的表头及其数值的单位（读取时换算）；必需的列标有 *。</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="43"/>
        <source>Delimiter %1, %2, time stamps in column &apos;%3&apos; (%4)%5.</source>
        <translation>分隔符 %1，%2，时间戳在列“%3”中（%4）%5。</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="44"/>
        <source>tab</source>
        <translation>制表符</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="45"/>
        <source>decimal commas</source>
        <translation>小数逗号</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="45"/>
        <source>decimal points</source>
        <translation>小数点</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="48"/>
        <source>, a units row under the header</source>
        <translation>，表头下有单位行</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="51"/>
        <source>Could not read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="52"/>
        <source>Choose, for each column DryTwin needs, the header your files use and the unit its values are in (converted when read); required columns are marked *. The proposal comes from the headers&apos; words and tag letters and the ranges of the first rows&apos; values: check it.</source>
        <translation>为 DryTwin 需要的每一列选择您文件中使用的表头及其数值的单位（读取时换算）；必需的列标有 *。建议来自表头中的词语、位号字母以及前几行数值的范围：请核对。</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="60"/>
        <source>DryTwin column</source>
        <translation>DryTwin 列</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="60"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="60"/>
        <source>Header in your file</source>
        <translation>您文件中的表头</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="61"/>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="61"/>
        <source>Unit in your file</source>
        <translation>您文件中的单位</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="61"/>
        <source>Why proposed</source>
        <translation>建议依据</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="74"/>
        <source>(not in the file)</source>
        <translation>（文件中没有）</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="116"/>
        <source>(none: cut runs at line stops and gaps)</source>
        <translation>（无：在停线和时间间断处切分生产段）</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="123"/>
        <source>Column that names the production run:</source>
        <translation>标识生产段的列：</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="128"/>
        <source>Run</source>
        <translation>生产段</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="128"/>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="128"/>
        <source>File lines</source>
        <translation>文件行</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="128"/>
        <source>Rows</source>
        <translation>行数</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="128"/>
        <source>Interpolated cells</source>
        <translation>插值单元格</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="128"/>
        <source>Ended by</source>
        <translation>结束原因</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="154"/>
        <source>The mapping is not complete: %1</source>
        <translation>映射不完整：%1</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="160"/>
        <source>With this mapping the file does not load: %1</source>
        <translation>按此映射无法加载该文件：%1</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="166"/>
        <source>The first %1 MB of the file give these production runs:</source>
        <translation>文件前 %1 MB 给出以下生产段：</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="167"/>
        <source>The file gives these production runs:</source>
        <translation>该文件给出以下生产段：</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="169"/>
        <source>Notes while reading: %1; the first: %2</source>
        <translation>读取时的提示：%1 条；第一条：%2</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="182"/>
        <source>one batch</source>
        <translation>单个批次</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="266"/>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::DataPanel</name>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="31"/>
        <source>Open file…</source>
        <translation>打开文件…</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="32"/>
        <source>Open folder…</source>
        <translation>打开文件夹…</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="33"/>
        <source>Column mapping…</source>
        <translation>列映射…</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="34"/>
        <source>Files with other column names: map them onto DryTwin&apos;s columns, then load</source>
        <translation>列名不同的文件：先映射到 DryTwin 的列，再加载</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="38"/>
        <source>Batches overlaid</source>
        <translation>批次叠加</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="38"/>
        <source>Batches one after another</source>
        <translation>批次首尾相接</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="39"/>
        <source>Batch</source>
        <translation>批次</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="39"/>
        <source>Rows</source>
        <translation>行数</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="39"/>
        <source>Kept</source>
        <translation>保留</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="39"/>
        <source>Length [min]</source>
        <translation>时长 [min]</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="40"/>
        <source>Mean X_out [% wb]</source>
        <translation>平均 X_out [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="40"/>
        <source>Mean T_hot [°C]</source>
        <translation>平均 T_hot [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="40"/>
        <source>Source</source>
        <translation>来源</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="54"/>
        <source>Batches (select several to overlay; drop files here):</source>
        <translation>批次（多选可叠加；可将文件拖放到此处）：</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="73"/>
        <source>Open batch file</source>
        <translation>打开批次文件</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="73"/>
        <location filename="../widgets/data/DataPanel.cpp" line="86"/>
        <source>Batch files (*.csv)</source>
        <translation>批次文件 (*.csv)</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="79"/>
        <source>Open data set folder</source>
        <translation>打开数据集文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="85"/>
        <source>A batch file with your column names</source>
        <translation>一个使用您的列名的批次文件</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="95"/>
        <source>Save the column mapping</source>
        <translation>保存列映射</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="95"/>
        <source>Mappings (*.json)</source>
        <translation>映射 (*.json)</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="151"/>
        <source>%1, lines %2–%3, from %4, ended by %5</source>
        <translation>%1，第 %2–%3 行，始于 %4，结束原因：%5</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="179"/>
        <source>Cleaning (paper §IV.A): %1 of %2 rows kept; dropped for X_HDT %3, T_HDT %4, feed %5, missing cells %6, impossible values %7. Split: the first %8 rows train, the last %9 test.</source>
        <translation>清洗（论文 §IV.A）：%2 行中保留 %1 行；剔除原因：X_HDT %3，T_HDT %4，进料 %5，缺失值 %6，不可能的值 %7。划分：前 %8 行用于训练，后 %9 行用于测试。</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="193"/>
        <source>Noted while reading (%1):</source>
        <translation>读取时的提示（%1）：</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::DiagnosticsPanel</name>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="26"/>
        <source>Evaluate</source>
        <translation>评估</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="27"/>
        <source>Evaluate a trained model to see its residuals.</source>
        <translation>评估已训练的模型以查看其残差。</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="30"/>
        <source>ACF [-]</source>
        <translation>自相关 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="31"/>
        <source>lag [s]</source>
        <translation>滞后 [s]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="33"/>
        <source>PSD [(% wb)²/Hz]</source>
        <translation>功率谱密度 [(% 湿基)²/Hz]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="34"/>
        <source>frequency [Hz]</source>
        <translation>频率 [Hz]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="39"/>
        <source>Models shown (tick to overlay):</source>
        <translation>显示的模型（勾选以叠加）：</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="43"/>
        <source>error [% wb]</source>
        <translation>误差 [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="60"/>
        <source>Physics model&apos;s error against</source>
        <translation>机理模型误差相对于</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="65"/>
        <source>CCF [-]</source>
        <translation>互相关 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="66"/>
        <source>lag of the input [s] (run Discover)</source>
        <translation>输入的滞后 [s]（请运行发现）</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="108"/>
        <source>%1: Ljung-Box p %2, residual mean %3 % wb</source>
        <translation>%1：Ljung-Box p = %2，残差均值 %3 % 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="144"/>
        <source>%1 (%2 % below 0.01 Hz)</source>
        <translation>%1（%2 % 低于 0.01 Hz）</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="150"/>
        <source>95 % band of white noise</source>
        <translation>白噪声 95 % 置信带</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="190"/>
        <source>every 10th kept row</source>
        <translation>保留行中每隔 10 行</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="218"/>
        <source>lag of the input [s]</source>
        <translation>输入的滞后 [s]</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::DiscoverPanel</name>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="22"/>
        <source>Discover</source>
        <translation>发现</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="23"/>
        <source>What does the simulation get wrong, and why? (score tests, fits, held-out gain)</source>
        <translation>仿真哪里出错，为什么？（得分检验、拟合、留出数据上的改进）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="24"/>
        <source>Extend the model</source>
        <translation>扩展模型</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="27"/>
        <source>Make the extended model (named causes, refitted h_HDT and k_HDT, residual models retrained) the session&apos;s model</source>
        <translation>将扩展后的模型（已命名的原因、重新拟合的 h_HDT 与 k_HDT、重新训练的残差模型）设为当前模型</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="29"/>
        <source>Run discovery on the loaded data with the current model.</source>
        <translation>用当前模型在已加载的数据上运行发现。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="31"/>
        <source>Cause</source>
        <translation>原因</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="31"/>
        <source>Score z</source>
        <translation>得分 z</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="31"/>
        <source>p (Holm)</source>
        <translation>p（Holm）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="31"/>
        <source>Fitted</source>
        <translation>已拟合</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="31"/>
        <source>Loss</source>
        <translation>损失</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="32"/>
        <source>Held-out</source>
        <translation>留出数据</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="32"/>
        <source>Before</source>
        <translation>之前</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="32"/>
        <source>After</source>
        <translation>之后</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="32"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="35"/>
        <source>X_out residual [% wb]</source>
        <translation>X_out 残差 [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="36"/>
        <source>T_out residual [°C]</source>
        <translation>T_out 残差 [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="37"/>
        <source>time, batches one after another [h]</source>
        <translation>时间，批次首尾相接 [h]</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="46"/>
        <source>Candidate causes, first round:</source>
        <translation>候选原因（第一轮）：</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="48"/>
        <source>Gain on the held-out part:</source>
        <translation>留出数据上的改进：</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="65"/>
        <source> The model is extended.</source>
        <translation> 模型已扩展。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="80"/>
        <source>the outlet-temperature error grows with the hot-air excess over ambient (bias by T_amb and T_hot)</source>
        <translation>出口温度误差随热风高出环境温度的幅度增大（按 T_amb 和 T_hot 分组的偏差）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="83"/>
        <source>the errors grow with feed rate and inlet moisture (bias by feed_kg_h and X_in_pct)</source>
        <translation>误差随进料量和入口水分增大（按 feed_kg_h 和 X_in_pct 分组的偏差）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="86"/>
        <source>the error drifts within every batch and resets at each batch start</source>
        <translation>误差在每个批次内漂移，并在每个批次开始时复位</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="88"/>
        <source>the outlet-moisture error follows the rate of change of the simulated outlet moisture, and the tube-outlet error does not</source>
        <translation>出口水分误差跟随模拟出口水分的变化率，而管道出口误差不跟随</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="92"/>
        <source>a steady outlet-moisture bias that the tube-outlet moisture does not share</source>
        <translation>出口水分存在稳定偏差，而管道出口水分没有</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="95"/>
        <source>the outlet error correlates with tube-outlet changes at a shifted lag</source>
        <translation>出口误差与管道出口的变化在偏移的滞后处相关</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="97"/>
        <source>the tube-outlet and outlet moisture are wetter than simulated, most where the tube dries furthest</source>
        <translation>管道出口和出口水分比模拟值更湿，在管道干燥程度最深处最明显</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="101"/>
        <source>the outlet-moisture error grows with ambient humidity while the tube-outlet error does not</source>
        <translation>出口水分误差随环境湿度增大，而管道出口误差不随之变化</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="105"/>
        <source>a steady bias of the tube-outlet and outlet moisture alike, larger where the tube dries less</source>
        <translation>干燥管出口与出口水分有相同的稳定偏差，干燥管干燥越少处越大</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="108"/>
        <source>after each hot-air setpoint step the outlet temperature and moisture move before the simulation, which follows the slow reading</source>
        <translation>每次热风设定值阶跃后，出口温度和水分先于仿真变化，仿真跟随的是迟缓的读数</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="111"/>
        <source>the inlet-moisture reading scatters from second to second while the outlet does not follow it, and the simulated outlet does</source>
        <translation>入口水分读数逐秒跳动，出口并不跟随，而仿真的出口却跟随</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="121"/>
        <source>a step of the hot-air setpoint logged at 1 s: a transport-time error delays the outlet temperature&apos;s response as much as the moisture&apos;s, a meter lag delays the moisture reading alone; or grab samples timed against the meter</source>
        <translation>以 1 s 记录一次热风设定值阶跃：输送时间误差使出口温度与水分的响应同样延迟，水分仪滞后只延迟水分读数；或对照水分仪定时取样</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="128"/>
        <source>oven-dry laboratory samples at the outlet against the meter and at the inlet against the gauge; or a tube-outlet moisture channel (X_hdt), which an inlet-gauge offset moves and an outlet-meter offset does not</source>
        <translation>在出口对照水分仪、在入口对照入口水分计做烘箱法实验室取样；或增加干燥管出口水分通道（X_hdt）：入口水分计偏差会使其变化，出口水分仪偏差不会</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="135"/>
        <source>a gas-temperature reading at the tube&apos;s outlet end at two feed rates: wall loss does not change with the feed, gas-phase cooling grows with it</source>
        <translation>在两种喂料量下测量干燥管出口端的气体温度：管壁散热不随喂料量变化，气相冷却随之增大</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="145"/>
        <source>it lowers one output&apos;s error by raising another&apos;s (compensation)</source>
        <translation>它以增大另一输出的误差为代价降低一个输出的误差（补偿）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="148"/>
        <source>its size is not consistent across batches or operating regions</source>
        <translation>其大小在各批次或各工况区间之间不一致</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="151"/>
        <source>it is below what the instruments can tell (practical floor)</source>
        <translation>它低于仪表能分辨的程度（实用下限）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="154"/>
        <source>the outlet temperature lags the model as much: the line is slower than the model, not the meter</source>
        <translation>出口温度同样滞后于模型：是产线比模型慢，而不是水分仪</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="157"/>
        <source>no clear held-out gain</source>
        <translation>在留出数据上没有明确的改进</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="172"/>
        <source>Fitted part by part (%1 parts) it lies between %2 and %3 %4: %5.</source>
        <translation>逐段拟合（%1 段）时其值在 %2 与 %3 %4 之间：%5。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="177"/>
        <source>consistent</source>
        <translation>一致</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="177"/>
        <source>not consistent</source>
        <translation>不一致</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="180"/>
        <source>Fitted on the cooler half of the data it removes %1 % of the warmer half&apos;s error.</source>
        <translation>用较冷的一半数据拟合，它消除较热一半数据误差的 %1 %。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="184"/>
        <source>It starts %1 min into the batch (95 % interval %2–%3 min).</source>
        <translation>它在批次开始后 %1 min 出现（95 % 区间 %2–%3 min）。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="191"/>
        <source>Not %1: fitted in its place it leaves %2 times the held-out error (p = %3).</source>
        <translation>不是 %1：以它代替拟合后留出误差为 %2 倍（p = %3）。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="192"/>
        <source>%1 fits these data about as well (held-out error %2 times, p = %3): the data cannot tell them apart.</source>
        <translation>%1 对这些数据拟合得差不多好（留出误差 %2 倍，p = %3）：数据无法区分二者。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="199"/>
        <source>To tell them apart: %1.</source>
        <translation>区分方法：%1。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="211"/>
        <source>it removes %1 % of the held-out squared error and %2 % of its fast part (the error about its moving average, where slow drift does not hide it)</source>
        <translation>它消除了留出数据平方误差的 %1 %，以及其快速部分（误差相对其滑动平均的部分，慢漂移不会掩盖它）的 %2 %</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="215"/>
        <source>it removes %1 % of the held-out squared error</source>
        <translation>它消除了留出数据平方误差的 %1 %</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="216"/>
        <source>%1 error before: bias %2 %3, within-batch trend %4 %3/h. With %5 (%6 = %7 %8, 95 % CI [%9, %10]) and h_HDT, k_HDT refitted, the held-out MAE of X_out falls from %11 to %12 % wb and of T_out from %13 to %14 °C (Diebold-Mariano p = %15); %16. Check on the plots: %17.</source>
        <translation>扩展前的%1误差：偏差 %2 %3，批次内趋势 %4 %3/h。加入 %5（%6 = %7 %8，95 % 置信区间 [%9, %10]）并重新拟合 h_HDT、k_HDT 后，留出数据上 X_out 的 MAE 从 %11 降至 %12 % 湿基，T_out 从 %13 降至 %14 °C（Diebold-Mariano p = %15）；%16。在图上检查：%17。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="220"/>
        <source>Outlet-moisture</source>
        <translation>出口水分</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="220"/>
        <source>Outlet-temperature</source>
        <translation>出口温度</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="250"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="253"/>
        <source>one of %1 (look-alikes)</source>
        <translation>%1 之一（相似原因）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="257"/>
        <source>Verdict: %1. No mechanism is named.</source>
        <translation>结论：%1。未命名任何机理。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="258"/>
        <source>Verdict: %1. Named: %2.</source>
        <translation>结论：%1。已命名：%2。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="265"/>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="265"/>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="286"/>
        <source>%1 at %2 s (ccf %3%4)</source>
        <translation>%1，滞后 %2 s（互相关 %3%4）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="290"/>
        <source>, significant</source>
        <translation>，显著</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="293"/>
        <source>&lt;p&gt;&lt;b&gt;%1&lt;/b&gt; error moves with: %2&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;%1&lt;/b&gt; 误差随以下变量变化：%2&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="302"/>
        <source>&lt;p&gt;&lt;b&gt;Round %1&lt;/b&gt;: %2 (held-out p = %3; removes %4 % of the error, %5 % of its fast part): %6&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;第 %1 轮&lt;/b&gt;：%2（保留集 p = %3；消除误差的 %4 %，其快速部分的 %5 %）：%6&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="309"/>
        <source>named</source>
        <translation>已确认</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="311"/>
        <source>&lt;p&gt;&amp;nbsp;&amp;nbsp;Not named: %1, because %2.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&amp;nbsp;&amp;nbsp;未认定：%1，因为%2。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="328"/>
        <source>&lt;p&gt;&lt;b&gt;Not named&lt;/b&gt;; what the data allow (95 %): %1&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;未确认&lt;/b&gt;；数据允许的范围（95 %）：%1&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="333"/>
        <source>&lt;p&gt;&lt;b&gt;Unexplained&lt;/b&gt; (%1): the error follows the simulated rate of change (a lag of %2 s would explain %3 % of it): the line&apos;s dynamics differ from the model&apos;s.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;未解释&lt;/b&gt;（%1）：误差跟随仿真值的变化率（%2 s 的滞后可解释其 %3 %）：产线的动态与模型不同。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="341"/>
        <source>&lt;p&gt;&lt;b&gt;Unexplained&lt;/b&gt; (%1): %2&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;未解释&lt;/b&gt;（%1）：%2&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="346"/>
        <source>&lt;p&gt;&lt;b&gt;The correction model learnt on the extended physics model predicts worse on the held-out part than the one on the starting model: Extend keeps the starting model and its correction model; the findings stand.&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;在扩展物理模型上学得的修正模型在留出数据上的预测比在初始模型上的差：“扩展”保留初始模型及其修正模型；结论仍然成立。&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="354"/>
        <source>&lt;p&gt;No structure that a mechanism explains.&lt;/p&gt;</source>
        <translation>&lt;p&gt;没有可由机理解释的结构。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="365"/>
        <source>MAE X_out (physics)</source>
        <translation>MAE X_out（机理）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="206"/>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="366"/>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="373"/>
        <source>% wb</source>
        <translation>% 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="367"/>
        <source>MAE T_out (physics)</source>
        <translation>MAE T_out（机理）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="206"/>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="368"/>
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="369"/>
        <source>R² X_out</source>
        <translation>R² X_out</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="370"/>
        <source>low-frequency share</source>
        <translation>低频占比</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="373"/>
        <source>MAE X_out (PGRL-CC)</source>
        <translation>MAE X_out（PGRL-CC）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="390"/>
        <source>starting model</source>
        <translation>初始模型</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="391"/>
        <source>extended model</source>
        <translation>扩展后的模型</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::ErrorText</name>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="16"/>
        <source>%1: no such file or folder</source>
        <translation>%1：文件或文件夹不存在</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="22"/>
        <source>%1: the required column &apos;%2&apos; is missing</source>
        <translation>%1：缺少必需的列“%2”</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="29"/>
        <source>%1, line %2, column %3: text &apos;%4&apos; in the numeric column &apos;%5&apos;</source>
        <translation>%1，第 %2 行，第 %3 列：数值列“%5”中出现文本“%4”</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="36"/>
        <source>%1, line %2, column %3: time does not increase</source>
        <translation>%1，第 %2 行，第 %3 列：时间未递增</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="43"/>
        <source>%1, line %2, column %3: %4</source>
        <translation>%1，第 %2 行，第 %3 列：%4</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="49"/>
        <source>Parameter %1 = %2 lies outside its range [%3, %4]</source>
        <translation>参数 %1 = %2 超出其范围 [%3, %4]</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="55"/>
        <source>No data loaded; open a batch file or folder first.</source>
        <translation>未加载数据；请先打开批次文件或文件夹。</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="58"/>
        <source>Cancelled by the user.</source>
        <translation>已被用户取消。</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::LineView3D</name>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="71"/>
        <source>moisture [% wb]</source>
        <translation>含水率 [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="71"/>
        <source>temperature [°C]</source>
        <translation>温度 [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="74"/>
        <location filename="../widgets/view3d/LineView3D.cpp" line="96"/>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="76"/>
        <source>Simulate the model to see the parcels.</source>
        <translation>运行模型仿真以查看物料团。</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="80"/>
        <source>Batch</source>
        <translation>批次</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="96"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="278"/>
        <source>%1 s of %2</source>
        <translation>%1 s / %2</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::MainWindow</name>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="56"/>
        <source>DryTwin</source>
        <translation>DryTwin</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="70"/>
        <source>Data</source>
        <translation>数据</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="71"/>
        <source>Model</source>
        <translation>模型</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="72"/>
        <source>Calibrate</source>
        <translation>标定</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="73"/>
        <source>Residual model</source>
        <translation>残差模型</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="74"/>
        <source>Diagnostics</source>
        <translation>诊断</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="75"/>
        <source>Discover</source>
        <translation>发现</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="76"/>
        <source>What-if MPC</source>
        <translation>假设分析 MPC</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="77"/>
        <source>3D line</source>
        <translation>三维产线</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="79"/>
        <source>Training</source>
        <translation>培训</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="82"/>
        <source>No data loaded. File ▸ Open data set…</source>
        <translation>未加载数据。文件 ▸ 打开数据集…</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="86"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="166"/>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="167"/>
        <source>&amp;Open batch file…</source>
        <translation>打开批次文件(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="169"/>
        <source>Open batch file</source>
        <translation>打开批次文件</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="169"/>
        <source>Batch files (*.csv)</source>
        <translation>批次文件 (*.csv)</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="175"/>
        <source>Open data set &amp;folder…</source>
        <translation>打开数据集文件夹(&amp;F)…</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="176"/>
        <source>Open data set folder</source>
        <translation>打开数据集文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="181"/>
        <source>&amp;Generate virtual-plant data…</source>
        <translation>生成虚拟装置数据(&amp;G)…</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="183"/>
        <source>Folder for the virtual plant&apos;s batches</source>
        <translation>虚拟装置批次的文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="192"/>
        <source>Open &amp;model…</source>
        <translation>打开模型(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="194"/>
        <source>Open model</source>
        <translation>打开模型</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="194"/>
        <location filename="../widgets/MainWindow.cpp" line="201"/>
        <source>Model files (*.json)</source>
        <translation>模型文件 (*.json)</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="199"/>
        <source>Save model &amp;as…</source>
        <translation>模型另存为(&amp;A)…</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="200"/>
        <source>Save model</source>
        <translation>保存模型</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="207"/>
        <source>Open &amp;project…</source>
        <translation>打开项目(&amp;P)…</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="209"/>
        <location filename="../widgets/MainWindow.cpp" line="212"/>
        <location filename="../widgets/MainWindow.cpp" line="407"/>
        <source>Open project</source>
        <translation>打开项目</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="209"/>
        <location filename="../widgets/MainWindow.cpp" line="219"/>
        <location filename="../widgets/MainWindow.cpp" line="229"/>
        <source>DryTwin projects (*.drytwin)</source>
        <translation>DryTwin 项目 (*.drytwin)</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="215"/>
        <source>&amp;Save project</source>
        <translation>保存项目(&amp;S)</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="218"/>
        <location filename="../widgets/MainWindow.cpp" line="223"/>
        <location filename="../widgets/MainWindow.cpp" line="229"/>
        <location filename="../widgets/MainWindow.cpp" line="232"/>
        <source>Save project</source>
        <translation>保存项目</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="227"/>
        <source>Save project as…</source>
        <translation>项目另存为…</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="235"/>
        <source>Recent projects</source>
        <translation>最近的项目</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="238"/>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="241"/>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="242"/>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="254"/>
        <source>The language changes when DryTwin is started again.</source>
        <translation>语言将在 DryTwin 重新启动后生效。</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="257"/>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="258"/>
        <source>&amp;About DryTwin</source>
        <translation>关于 DryTwin(&amp;A)</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="259"/>
        <source>About DryTwin</source>
        <translation>关于 DryTwin</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="260"/>
        <source>About &amp;Qt</source>
        <translation>关于 Qt(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="264"/>
        <source>&lt;h3&gt;DryTwin %1&lt;/h3&gt;&lt;p&gt;Digital-twin workbench for pneumatic drying lines, implementing the PGRL-CC method.&lt;/p&gt;&lt;table&gt;</source>
        <translation>&lt;h3&gt;DryTwin %1&lt;/h3&gt;&lt;p&gt;气流干燥生产线数字孪生工作台，实现 PGRL-CC 方法。&lt;/p&gt;&lt;table&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="328"/>
        <location filename="../widgets/MainWindow.cpp" line="335"/>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="341"/>
        <source>Project saved to %1</source>
        <translation>项目已保存到 %1</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="349"/>
        <source>cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="358"/>
        <source>%1 is not a DryTwin project (%2)</source>
        <translation>%1 不是 DryTwin 项目（%2）</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::ModelPanel</name>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="49"/>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="49"/>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="49"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="49"/>
        <source>Lower</source>
        <translation>下限</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="49"/>
        <source>Upper</source>
        <translation>上限</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="49"/>
        <source>Source</source>
        <translation>来源</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="49"/>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="52"/>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="53"/>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="61"/>
        <source>Physics switches</source>
        <translation>物理开关</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="63"/>
        <source>clamp water activity (Eq. 2)</source>
        <translation>限制水分活度（式 2）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="63"/>
        <source>bound-water latent heat (Eq. 4)</source>
        <translation>结合水潜热（式 4）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="64"/>
        <source>moisture-dependent heat capacity (Eq. 3)</source>
        <translation>随含水率变化的比热（式 3）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="65"/>
        <source>consistent energy balance (Eqs. 12, 14, 19; off: as printed)</source>
        <translation>一致的能量平衡（式 12、14、19；关闭：按原文）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="81"/>
        <source>Simulate</source>
        <translation>仿真</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="82"/>
        <source>Run the physics model over every batch with these parameters</source>
        <translation>用这些参数对每个批次运行机理模型</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="89"/>
        <source>Double-click a value to edit it; it is checked against its bounds.</source>
        <translation>双击数值进行编辑；将按其上下限检查。</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="99"/>
        <source>Batch:</source>
        <translation>批次：</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="103"/>
        <source>X_out [% wb]</source>
        <translation>X_out [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="104"/>
        <source>T_out [°C]</source>
        <translation>T_out [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="105"/>
        <source>X_HDT [% wb]</source>
        <translation>X_HDT [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="106"/>
        <source>T_HDT [°C]</source>
        <translation>T_HDT [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="143"/>
        <source>%1 must lie in [%2, %3] %4; it stays %5.</source>
        <translation>%1 必须在 [%2, %3] %4 之内；保持为 %5。</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="204"/>
        <location filename="../widgets/model/ModelPanel.cpp" line="212"/>
        <source>measured</source>
        <translation>实测</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="224"/>
        <source>physics model</source>
        <translation>机理模型</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::MpcPanel</name>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="38"/>
        <source>Open scenario…</source>
        <translation>打开情景…</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="42"/>
        <source>The scenario as JSON (schema in docs/mpc.md): setpoint steps, input steps and ramps, hidden mechanisms switched on mid-run, noise. Edits are checked when you run.</source>
        <translation>以 JSON 表示的情景（格式见 docs/mpc.md）：设定值阶跃、输入阶跃与斜坡、运行中途开启的隐藏机理、噪声。运行时检查修改。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="50"/>
        <source>Run scenario</source>
        <translation>运行情景</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="52"/>
        <source>Show the horizon the controllers predicted at this decision</source>
        <translation>显示控制器在此决策时刻预测的时域</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="53"/>
        <source>Runs the scenario against the virtual plant once per controller.</source>
        <translation>对虚拟装置逐个控制器运行该情景。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="55"/>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="55"/>
        <source>IAE [%·s]</source>
        <translation>IAE [%·s]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="55"/>
        <source>Effort [K²]</source>
        <translation>控制量 [K²]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="55"/>
        <source>Violations [%]</source>
        <translation>越限 [%]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="56"/>
        <source>Solve median [ms]</source>
        <translation>求解时间中位数 [ms]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="56"/>
        <source>Fallbacks</source>
        <translation>回退次数</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="56"/>
        <source>Model gain [%/K]</source>
        <translation>模型增益 [%/K]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="58"/>
        <source>X_out, true [% wb]</source>
        <translation>X_out 真实值 [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="59"/>
        <source>T_hot setpoint [°C]</source>
        <translation>T_hot 设定值 [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="71"/>
        <source>prediction at</source>
        <translation>预测时刻</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="94"/>
        <source>Open scenario</source>
        <translation>打开情景</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="94"/>
        <source>Scenarios (*.json)</source>
        <translation>情景 (*.json)</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="109"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="126"/>
        <source>Cannot write %1</source>
        <translation>无法写入 %1</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="140"/>
        <source>Choose at least one controller.</source>
        <translation>请至少选择一个控制器。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="143"/>
        <source>Running…</source>
        <translation>正在运行…</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="164"/>
        <source>skipped</source>
        <translation>已跳过</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="178"/>
        <source>setpoint</source>
        <translation>设定值</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="186"/>
        <source>band</source>
        <translation>允许带</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="202"/>
        <source>%1 predicted at %2 s</source>
        <translation>%1 在 %2 s 时的预测</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="211"/>
        <source>%1. IAE and violations on the product&apos;s true outlet moisture; the plant&apos;s own gain is %2 % wb/K.</source>
        <translation>%1。IAE 与越限按产品真实出口含水率计；装置自身增益为 %2 % 湿基/K。</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::PlotStack</name>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="82"/>
        <source>Ctrl+click: cursor A, Shift+click: cursor B, Alt+click: time cursor; drag to zoom, right click to zoom out, middle drag to pan</source>
        <translation>Ctrl+单击：游标 A，Shift+单击：游标 B，Alt+单击：时间游标；拖动放大，右键缩小，中键拖动平移</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="86"/>
        <source>Export…</source>
        <translation>导出…</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="87"/>
        <source>Save these plots as PNG, SVG or PDF</source>
        <translation>将这些图表保存为 PNG、SVG 或 PDF</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="160"/>
        <source>time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="335"/>
        <source>A %1</source>
        <translation>A %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="338"/>
        <source>B %1</source>
        <translation>B %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="341"/>
        <source>Δx %1</source>
        <translation>Δx %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="345"/>
        <source>%1: Δ %2</source>
        <translation>%1：Δ %2</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="349"/>
        <source>time cursor %1 s</source>
        <translation>时间游标 %1 s</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="423"/>
        <source>cannot write %1</source>
        <translation>无法写入 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="401"/>
        <source>DryTwin plots</source>
        <translation>DryTwin 图表</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="447"/>
        <source>unknown format &apos;%1&apos;: use .png, .svg or .pdf</source>
        <translation>未知格式“%1”：请使用 .png、.svg 或 .pdf</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="454"/>
        <source>Export plots</source>
        <translation>导出图表</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="455"/>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF (*.pdf)</source>
        <translation>PNG 图像 (*.png);;SVG 矢量图 (*.svg);;PDF (*.pdf)</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="461"/>
        <source>Export failed: %1</source>
        <translation>导出失败：%1</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="463"/>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::ResidualPanel</name>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="27"/>
        <source>chosen by validation (16, 32, 60)</source>
        <translation>由验证选择（16、32、60）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="31"/>
        <source>Eq. 30: constrained fit with certificate</source>
        <translation>式 30：带证书的约束拟合</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="31"/>
        <source>eigenvalues pulled in after the fit</source>
        <translation>拟合后将特征值收缩</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="32"/>
        <source>orthogonal projection P⊥ (Eq. 27)</source>
        <translation>正交投影 P⊥（式 27）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="34"/>
        <source>Train PGRL-CC and the baselines</source>
        <translation>训练 PGRL-CC 及基线模型</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="36"/>
        <source>residual lags</source>
        <translation>残差滞后阶数</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="37"/>
        <source>stability</source>
        <translation>稳定性</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="41"/>
        <source>Trains on the chronological 70 % and evaluates on the rest; settings are chosen inside the training part.</source>
        <translation>按时间顺序用前 70 % 训练，其余部分评估；设置在训练部分内选定。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="44"/>
        <source>Run a What-if MPC scenario to compare each model&apos;s steady gain of X_out to the hot air with the plant&apos;s.</source>
        <translation>运行一次假设 MPC 情景，即可将各模型 X_out 对热风的稳态增益与装置的增益比较。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="47"/>
        <source>Model</source>
        <translation>模型</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="47"/>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="59"/>
        <source>MAE X_out [% wb]</source>
        <translation>MAE X_out [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="47"/>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="59"/>
        <source>R² X_out</source>
        <translation>R² X_out</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="47"/>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="59"/>
        <source>MAE T_out [°C]</source>
        <translation>MAE T_out [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="48"/>
        <source>skill 1 step</source>
        <translation>1 步技能值</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="48"/>
        <source>skill 30 steps</source>
        <translation>30 步技能值</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="50"/>
        <source>imaginary part</source>
        <translation>虚部</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="51"/>
        <source>real part</source>
        <translation>实部</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="53"/>
        <source>skill: MAE over the better reference [-]</source>
        <translation>技能值：MAE 与较优参考之比 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="54"/>
        <source>forecast horizon [steps of 1 s]</source>
        <translation>预测步长 [1 s 步]</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="57"/>
        <source>Ablation (paper Table 3)</source>
        <translation>消融实验（论文表 3）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="58"/>
        <source>Train and evaluate every variant of Table 3 on this model (a few minutes)</source>
        <translation>在此模型上训练并评估表 3 的每个变体（需几分钟）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="59"/>
        <source>Variant</source>
        <translation>变体</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="60"/>
        <source>MAE X_out, extrapolation</source>
        <translation>MAE X_out（外推）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="99"/>
        <source>%1 %2 (%3 %)</source>
        <translation>%1 %2（%3 %）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="104"/>
        <source>Steady gain of X_out to the hot-air setpoint [% wb per K] at the scenario&apos;s start: the plant (open-loop step test) %1; each model as its MPC saw it, and how far from the plant&apos;s: %2. A learnt residual&apos;s response to the setpoint plan comes from the physics model, since data under the plant&apos;s own loop cannot tell it from the disturbances the loop answered.</source>
        <translation>情景起点处 X_out 对热风设定值的稳态增益 [% wb/K]：装置（开环阶跃试验）%1；各模型在其 MPC 中的增益及与装置的偏差：%2。学习得到的残差对设定值计划的响应取自物理模型，因为装置自身闭环下的数据无法将其与闭环所应对的扰动区分开。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="133"/>
        <source>Training…</source>
        <translation>正在训练…</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="169"/>
        <source>skill 1 (ties the better reference)</source>
        <translation>技能值 1（与较优参考持平）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="179"/>
        <source>unit circle</source>
        <translation>单位圆</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="193"/>
        <source>A unconstrained (ρ = %1)</source>
        <translation>无约束 A（ρ = %1）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="199"/>
        <source>A with Eq. 30 (ρ = %1)</source>
        <translation>式 30 约束后的 A（ρ = %1）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="226"/>
        <source> Slowest contraction of A: %1 per step (half-life %2 s).</source>
        <translation> A 的最慢收缩：每步 %1（半衰期 %2 s）。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="230"/>
        <source>Held-out part: %1 rows. Skill below 1 beats both reference predictors (the last measurement held, and the PBM with its last error held).</source>
        <translation>留出部分：%1 行。技能值低于 1 表示优于两个参考预测器（保持最后一次测量值，以及保持最后误差的 PBM）。</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::Series</name>
    <message>
        <location filename="../widgets/common/Series.cpp" line="12"/>
        <source>T_hot [°C]</source>
        <translation>T_hot [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="14"/>
        <source>feed [kg/h]</source>
        <translation>进料 [kg/h]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="16"/>
        <source>X_in [% wb]</source>
        <translation>X_in [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="18"/>
        <source>T_amb [°C]</source>
        <translation>T_amb [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="20"/>
        <source>RH [%]</source>
        <translation>相对湿度 [%]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="22"/>
        <source>X_HDT [% wb]</source>
        <translation>X_HDT [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="24"/>
        <source>X_out [% wb]</source>
        <translation>X_out [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="26"/>
        <source>T_out [°C]</source>
        <translation>T_out [°C]</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::TrainingPanel</name>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="111"/>
        <source>The line&apos;s conditions: initial levels, load changes, seed (docs/mpc.md)</source>
        <translation>产线条件：初始水平、负荷变化、随机种子（docs/mpc.md）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="112"/>
        <source>Start session</source>
        <translation>开始会话</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="113"/>
        <source>Instructor view</source>
        <translation>教员视图</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="115"/>
        <source>Shows the instructor&apos;s controls, the faults, the true moisture and the score; hide it before handing the screen to the trainee</source>
        <translation>显示教员的控制、故障、真实含水率和得分；将屏幕交给学员前请隐藏</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="117"/>
        <source>No session</source>
        <translation>无会话</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="126"/>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="133"/>
        <source> % wb</source>
        <translation> % 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="135"/>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="142"/>
        <source>Operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="144"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="148"/>
        <source>X_out setpoint</source>
        <translation>X_out 设定值</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="149"/>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="153"/>
        <source>Diagnose the recording…</source>
        <translation>诊断记录…</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="154"/>
        <source>Saves what the line recorded so far as a batch file and opens it, so that the Discover tab can show what the model gets wrong</source>
        <translation>将产线至今的记录保存为批次文件并打开，以便“发现”页显示模型哪里出错</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="157"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="498"/>
        <source>No fault</source>
        <translation>无故障</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="161"/>
        <source>Name the cause</source>
        <translation>给出原因</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="164"/>
        <source>Trainee</source>
        <translation>学员</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="171"/>
        <source>Causes named (session time):</source>
        <translation>已给出的原因（会话时间）：</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="175"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="483"/>
        <source>Freeze</source>
        <translation>冻结</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="179"/>
        <source> min</source>
        <translation> 分钟</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="180"/>
        <source>Run ahead</source>
        <translation>快进</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="181"/>
        <source>Runs the line this much further at full speed</source>
        <translation>以最快速度让产线再运行这么久</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="183"/>
        <source>label (default: the time)</source>
        <translation>标签（默认：时间）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="184"/>
        <source>Take snapshot</source>
        <translation>拍摄快照</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="187"/>
        <source>Restore selected</source>
        <translation>恢复所选快照</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="197"/>
        <source> s from now</source>
        <translation> 秒后</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="198"/>
        <source>Inject fault</source>
        <translation>注入故障</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="199"/>
        <source>Fault</source>
        <translation>故障</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="199"/>
        <source>Strength</source>
        <translation>强度</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="199"/>
        <source>Acts from</source>
        <translation>起作用时间</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="199"/>
        <source>Found after</source>
        <translation>发现用时</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="203"/>
        <source>Save session…</source>
        <translation>保存会话…</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="204"/>
        <source>Open session…</source>
        <translation>打开会话…</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="205"/>
        <source>Instructor</source>
        <translation>教员</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="218"/>
        <source>Clock and snapshots</source>
        <translation>时钟与快照</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="226"/>
        <source>Faults</source>
        <translation>故障</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="230"/>
        <source>A session file holds the scenario, every event (faults, snapshots, answers) and the recording as a batch file; reopening replays it to the same data.</source>
        <translation>会话文件包含工况、每个事件（故障、快照、回答）以及作为批次文件的记录；重新打开时会回放得到相同的数据。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="239"/>
        <source>Session file</source>
        <translation>会话文件</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="242"/>
        <source>Start a session: the line runs live under its PI loop.</source>
        <translation>开始会话：产线在其 PI 回路下实时运行。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="259"/>
        <source>X_out [% wb]</source>
        <translation>X_out [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="260"/>
        <source>T_hot [°C]</source>
        <translation>T_hot [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="261"/>
        <source>Feed [t/h]</source>
        <translation>进料 [t/h]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="262"/>
        <source>X_in [% wb]</source>
        <translation>X_in [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="263"/>
        <source>session time [min]</source>
        <translation>会话时间 [min]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="265"/>
        <source>band</source>
        <translation>允许带</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="267"/>
        <source>setpoint</source>
        <translation>设定值</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="268"/>
        <source>X_out measured</source>
        <translation>X_out 测量值</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="269"/>
        <source>X_out true (instructor)</source>
        <translation>X_out 真实值（教员）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="272"/>
        <source>T_hot setpoint</source>
        <translation>T_hot 设定值</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="273"/>
        <source>T_hot</source>
        <translation>T_hot</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="274"/>
        <source>feed</source>
        <translation>进料</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="275"/>
        <source>X_in</source>
        <translation>X_in</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="280"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="281"/>
        <source>Stops the replay or the run ahead; the line stays where it got to</source>
        <translation>停止回放或快进；产线停留在已运行到的位置</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="283"/>
        <source>Scenario</source>
        <translation>工况</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="345"/>
        <source>Select a snapshot to restore.</source>
        <translation>请选择要恢复的快照。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="355"/>
        <source>Save the session into a folder</source>
        <translation>将会话保存到文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="362"/>
        <source>Open a training session</source>
        <translation>打开培训会话</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="362"/>
        <source>Sessions (*.json)</source>
        <translation>会话 (*.json)</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="371"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="378"/>
        <source>Recording opened for diagnosis: %1. Run Discover on it, then name the cause here.</source>
        <translation>已打开记录以供诊断：%1。请在其上运行“发现”，然后在此给出原因。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="382"/>
        <source>Session saved: %1</source>
        <translation>会话已保存：%1</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="415"/>
        <source>Session started: the line runs under its PI loop. The MPC controllers use the model loaded now.</source>
        <translation>会话已开始：产线在其 PI 回路下运行。MPC 控制器使用当前加载的模型。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="419"/>
        <source>The previous session was saved in %1.</source>
        <translation>上一个会话已保存在 %1。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="432"/>
        <source>Replaying %1…</source>
        <translation>正在回放 %1…</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="478"/>
        <source>Session reopened at %1, frozen: the instructor resumes it.</source>
        <translation>会话已在 %1 处重新打开并冻结：由教员继续。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="480"/>
        <source>finished</source>
        <translation>已结束</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="480"/>
        <source>FROZEN</source>
        <translation>已冻结</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="480"/>
        <source>running %1×</source>
        <translation>运行中 %1×</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="482"/>
        <source>%1  t = %2 / %3  (%4)</source>
        <translation>%1  t = %2 / %3（%4）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="483"/>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="493"/>
        <source>Setpoint %1 % wb, band ±%2 % wb</source>
        <translation>设定值 %1 % 湿基，允许带 ±%2 % 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="494"/>
        <source>MPC fell back: %1</source>
        <translation>MPC 已回退：%1</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="498"/>
        <source>%1  %2</source>
        <translation>%1  %2</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="505"/>
        <source>%1 (at %2)</source>
        <translation>%1（于 %2）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="515"/>
        <source>not acting yet</source>
        <translation>尚未起作用</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="515"/>
        <source>not found</source>
        <translation>未发现</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="518"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="529"/>
        <source>&lt;b&gt;Score %1 / 100&lt;/b&gt; — faults found %2 of %3, wrong answers %4, product out of the band %5 % of the time (%6 kg)</source>
        <translation>&lt;b&gt;得分 %1 / 100&lt;/b&gt; — 找到故障 %2 / %3，错误回答 %4，产品超出允许带的时间占 %5 %（%6 kg）</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::TrainingRunner</name>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="263"/>
        <source>Setpoint</source>
        <translation>设定值</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="269"/>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="277"/>
        <source>Inject fault</source>
        <translation>注入故障</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="285"/>
        <source>Freeze</source>
        <translation>冻结</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="294"/>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="303"/>
        <source>Snapshot</source>
        <translation>快照</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="309"/>
        <source>Restore</source>
        <translation>恢复</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="315"/>
        <source>Name the cause</source>
        <translation>给出原因</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::Workbench</name>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="27"/>
        <source>%1 is queued behind the running job</source>
        <translation>%1 已排队，等待当前任务完成</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="38"/>
        <source>%1 was cancelled; nothing changed.</source>
        <translation>%1 已取消；未作任何更改。</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="39"/>
        <source>%1 failed: %2</source>
        <translation>%1 失败：%2</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="51"/>
        <source>Read the model</source>
        <translation>读取模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="64"/>
        <source>Loading %1…</source>
        <translation>正在加载 %1…</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="73"/>
        <source>Load %1</source>
        <translation>加载 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="88"/>
        <source>%1: %2 batches, %3 rows, %4 missing cells; the cleaning keeps %5 rows</source>
        <translation>%1：%2 个批次，%3 行，%4 个缺失值；清洗后保留 %5 行</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="106"/>
        <source>Open model %1</source>
        <translation>打开模型 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="109"/>
        <source>Model %1 opened</source>
        <translation>已打开模型 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="116"/>
        <source>Save model</source>
        <translation>保存模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="125"/>
        <source>Model saved to %1</source>
        <translation>模型已保存到 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="131"/>
        <source>Set %1</source>
        <translation>设置 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="146"/>
        <source>Set the model</source>
        <translation>设置模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="159"/>
        <source>Simulate</source>
        <translation>仿真</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="166"/>
        <source>Simulated %1 batches; mean outlet-moisture MAE %2 % wb</source>
        <translation>已仿真 %1 个批次；出口含水率平均 MAE %2 % 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="175"/>
        <source>Calibrate</source>
        <translation>标定</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="179"/>
        <source>Calibration %1: loss %2 → %3</source>
        <translation>标定 %1：损失 %2 → %3</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="196"/>
        <source>Train</source>
        <translation>训练</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="199"/>
        <source>Trained PGRL-CC and the baselines</source>
        <translation>已训练 PGRL-CC 及基线模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="208"/>
        <source>Evaluate</source>
        <translation>评估</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="217"/>
        <source>Discover</source>
        <translation>发现</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="220"/>
        <source>Discovery: %1</source>
        <translation>发现：%1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="227"/>
        <source>What-if scenario</source>
        <translation>假设情景</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="242"/>
        <source>Ablation</source>
        <translation>消融实验</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="245"/>
        <source>Ablation: %1 variants trained and evaluated</source>
        <translation>消融实验：已训练并评估 %1 个变体</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="252"/>
        <source>Generate</source>
        <translation>生成</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="254"/>
        <source>Wrote %1 virtual-plant batches to %2</source>
        <translation>已将 %1 个虚拟装置批次写入 %2</translation>
    </message>
</context>
</TS>
