<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>ColumnMeanings</name>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="104"/>
        <source>time since batch start</source>
        <translation>批次开始以来的时间</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="105"/>
        <source>hot-air temperature setpoint</source>
        <translation>热风温度设定值</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="106"/>
        <source>measured hot-air temperature at the tube inlet</source>
        <translation>管道入口处实测热风温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="107"/>
        <source>air speed in the drying tube</source>
        <translation>干燥管内风速</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="108"/>
        <source>wet feed rate entering the tube</source>
        <translation>进入干燥管的湿物料流量</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="109"/>
        <source>inlet moisture</source>
        <translation>入口水分</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="110"/>
        <source>inlet material temperature</source>
        <translation>入口物料温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="111"/>
        <source>ambient air temperature</source>
        <translation>环境空气温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="112"/>
        <source>ambient relative humidity</source>
        <translation>环境相对湿度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="113"/>
        <source>moisture at the tube outlet</source>
        <translation>管道出口处含水率</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="114"/>
        <source>material temperature at the tube outlet</source>
        <translation>管道出口处物料温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="115"/>
        <source>final outlet moisture after the winnower</source>
        <translation>风选机后最终出口含水率</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="116"/>
        <source>final outlet temperature after the winnower</source>
        <translation>风选机后最终出口温度</translation>
    </message>
</context>
<context>
    <name>DiscoverPanel</name>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="119"/>
        <source>compensation</source>
        <translation>相互补偿</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="120"/>
        <source>inconsistent</source>
        <translation>各批次不一致</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="121"/>
        <source>not constant</source>
        <translation>批次内不恒定</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="122"/>
        <source>within normal range</source>
        <translation>在正常范围内</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="123"/>
        <source>not on every output</source>
        <translation>并非每个输出都改善</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="124"/>
        <source>below the floor</source>
        <translation>低于实用下限</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="125"/>
        <source>no held-out gain</source>
        <translation>留出集无增益</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="126"/>
        <source>its look-alike</source>
        <translation>是其相似原因</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="127"/>
        <source>line dynamics</source>
        <translation>产线自身动态</translation>
    </message>
</context>
<context>
    <name>DisplayNames</name>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="20"/>
        <source>Physics model</source>
        <translation>物理模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="22"/>
        <source>Physics + learnt correction (PGRL-CC)</source>
        <translation>物理模型 + 学习修正（PGRL-CC）</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="24"/>
        <source>Physics + input-only correction</source>
        <translation>物理模型 + 仅输入修正</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="26"/>
        <source>LSTM (black box)</source>
        <translation>LSTM（黑箱）</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="28"/>
        <source>PI loop (the plant&apos;s own)</source>
        <translation>PI 回路（装置自带）</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="38"/>
        <source>Last measurement held</source>
        <translation>保持最后测量值</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="41"/>
        <source>Physics model, last error held</source>
        <translation>物理模型，保持最后误差</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="48"/>
        <source>hot-air setpoint</source>
        <translation>热风设定值</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="49"/>
        <source>hot-air temperature</source>
        <translation>热风温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="50"/>
        <source>air speed</source>
        <translation>风速</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="51"/>
        <source>feed rate</source>
        <translation>进料量</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="52"/>
        <source>inlet moisture</source>
        <translation>入口水分</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="53"/>
        <source>inlet material temperature</source>
        <translation>入口物料温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="54"/>
        <source>ambient temperature</source>
        <translation>环境温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="55"/>
        <source>ambient humidity</source>
        <translation>环境湿度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="56"/>
        <location filename="../widgets/common/DisplayNames.cpp" line="61"/>
        <source>outlet moisture</source>
        <translation>出口水分</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="57"/>
        <location filename="../widgets/common/DisplayNames.cpp" line="62"/>
        <source>outlet temperature</source>
        <translation>出口温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="58"/>
        <location filename="../widgets/common/DisplayNames.cpp" line="63"/>
        <source>tube-outlet moisture</source>
        <translation>管道出口水分</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="59"/>
        <location filename="../widgets/common/DisplayNames.cpp" line="64"/>
        <source>tube-outlet temperature</source>
        <translation>管道出口温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="65"/>
        <source>model error, outlet moisture</source>
        <translation>模型误差，出口水分</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="66"/>
        <source>model error, outlet temperature</source>
        <translation>模型误差，出口温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="67"/>
        <source>model error, tube-outlet moisture</source>
        <translation>模型误差，管道出口水分</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="68"/>
        <source>model error, tube-outlet temperature</source>
        <translation>模型误差，管道出口温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="70"/>
        <source>model&apos;s tube-outlet moisture</source>
        <translation>模型计算的管道出口水分</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="71"/>
        <source>model&apos;s tube-outlet temperature</source>
        <translation>模型计算的管道出口温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="72"/>
        <source>model&apos;s moisture on the conveyor</source>
        <translation>模型计算的输送带上水分</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="73"/>
        <source>model&apos;s temperature on the conveyor</source>
        <translation>模型计算的输送带上温度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="83"/>
        <source>tube-wall heat loss</source>
        <translation>管壁散热</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="84"/>
        <source>drying air cooling along the tube</source>
        <translation>干燥风沿管降温</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="85"/>
        <source>heat-transfer fouling</source>
        <translation>传热结垢</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="86"/>
        <source>slow outlet moisture meter</source>
        <translation>出口水分仪响应慢</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="87"/>
        <source>outlet moisture meter offset</source>
        <translation>出口水分仪偏差</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="88"/>
        <source>conveyor transport time off</source>
        <translation>输送时间偏差</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="89"/>
        <source>slower drying below critical moisture</source>
        <translation>低于临界含水率时干燥变慢</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="90"/>
        <source>moisture taken back on the conveyor</source>
        <translation>输送中回潮</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="91"/>
        <source>inlet moisture gauge offset</source>
        <translation>入口水分仪偏差</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="92"/>
        <source>slow hot-air thermocouple</source>
        <translation>热风热电偶响应慢</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="93"/>
        <source>noisy inlet moisture gauge</source>
        <translation>入口水分仪噪声大</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="94"/>
        <source>outlet mixing</source>
        <translation>出口混合</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="124"/>
        <source>seconds since the start</source>
        <translation>自开始起的秒数</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="125"/>
        <source>date and time, ISO 8601 (2024-05-31T08:00:00)</source>
        <translation>日期和时间，ISO 8601 格式（2024-05-31T08:00:00）</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="126"/>
        <source>year/month/day and time</source>
        <translation>年/月/日 及时间</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="127"/>
        <source>day.month.year and time</source>
        <translation>日.月.年 及时间</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="128"/>
        <source>day/month/year and time</source>
        <translation>日/月/年 及时间</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="129"/>
        <source>month/day/year and time</source>
        <translation>月/日/年 及时间</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="130"/>
        <source>day-month name-year and time</source>
        <translation>日-月份名-年 及时间</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="131"/>
        <source>spreadsheet day numbers</source>
        <translation>电子表格日期序号</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="132"/>
        <source>Unix time in seconds</source>
        <translation>Unix 时间（秒）</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="133"/>
        <source>Unix time in milliseconds</source>
        <translation>Unix 时间（毫秒）</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="142"/>
        <source>line stop</source>
        <translation>产线停机</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="143"/>
        <source>gap in the recording</source>
        <translation>记录中断</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="144"/>
        <source>next batch id</source>
        <translation>下一批次编号</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="145"/>
        <source>clock jump</source>
        <translation>时钟跳变</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="146"/>
        <source>end of file</source>
        <translation>文件结束</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="158"/>
        <source>DryTwin&apos;s own column name</source>
        <translation>DryTwin 自身的列名</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="161"/>
        <source>time stamps: %1</source>
        <translation>时间戳：%1</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="167"/>
        <source>values in %1</source>
        <translation>数值在 %1 之间</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="170"/>
        <source>words of the header</source>
        <translation>列标题中的词</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="172"/>
        <source>tag letters %1</source>
        <translation>位号字母 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="177"/>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="189"/>
        <source>%1: second %2 of %3</source>
        <translation>%1：第 %2 秒，共 %3 秒</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="199"/>
        <source>outlet response time (meter lag or transport time)</source>
        <translation>出口响应时间（仪表滞后或输送时间）</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="203"/>
        <source>moisture offset (outlet meter or inlet gauge)</source>
        <translation>水分偏差（出口水分仪或入口水分仪）</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="206"/>
        <source>air temperature in the tube (wall loss or air cooling)</source>
        <translation>管内风温（管壁散热或风冷却）</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="217"/>
        <location filename="../widgets/common/DisplayNames.cpp" line="231"/>
        <source>% wb</source>
        <translation>% 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="232"/>
        <source>% db</source>
        <translation>% 干基</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="233"/>
        <source>fraction, wet basis</source>
        <translation>分数，湿基</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="234"/>
        <source>fraction</source>
        <translation>分数</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="235"/>
        <source>min</source>
        <translation>分钟</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="236"/>
        <source>% RH</source>
        <translation>% 相对湿度</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="245"/>
        <source>Cause found</source>
        <translation>找到原因</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="246"/>
        <source>Cause found: %1</source>
        <translation>找到原因：%1</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="251"/>
        <source>No cause named: no candidate passed every check (the table says why each was not named)</source>
        <translation>未指认原因：没有候选原因通过全部检验（表中给出每个未被指认的理由）</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="346"/>
        <source>widened because neighbouring rows are alike and not independent evidence</source>
        <translation>已加宽：相邻样本彼此相似，不是独立的证据</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="354"/>
        <source>Intervals: sandwich covariance with a Newey-West middle term.</source>
        <translation>区间：夹心协方差，中间项为 Newey-West。</translation>
    </message>
    <message>
        <source>No cause found: what the model gets wrong is within the measurements&apos; noise</source>
        <translation>未找到原因：模型的误差在测量噪声范围之内</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="256"/>
        <source>Something is left that no known cause explains</source>
        <translation>仍有已知原因无法解释的结构</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="265"/>
        <source>Next: nothing changed since the reference period that the model needs to account for. To see smaller changes, record longer or more batches.</source>
        <translation>下一步：自参考期以来没有需要模型考虑的变化。若要看到更小的变化，请记录更长或更多的批次。</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="271"/>
        <source>Next: something changed since the reference period that no known cause explains. The evidence says which measurement the error follows; check that transmitter and the maintenance log around the time the change began. If the reference period itself was not a good time for the line, choose another one.</source>
        <translation>下一步：自参考期以来发生了没有已知原因能解释的变化。证据说明了误差跟随哪个测量值；请检查该变送器以及变化开始前后的维护记录。如果参考期本身并不是产线运行良好的时段，请另选一个。</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="279"/>
        <source>Next: check that part of the line (the evidence says where and from when), then “Extend the model” to add the cause and see how much the simulation improves.</source>
        <translation>下一步：检查产线的这一部分（证据说明了位置和起始时间），然后点击“扩展模型”加入该原因，看仿真改善了多少。</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="286"/>
        <source>Next: a cause fits these data and predicts better but failed a check (the table says which and why); one data set alone cannot tell it from the line&apos;s own structure. Compare with data from a time when the line ran well (“Compare with a reference period”), or record longer or more batches.</source>
        <translation>下一步：有一个原因能拟合这些数据并预测得更好，但未通过某项检查（表中说明是哪一项及原因）；仅凭一个数据集无法把它与产线自身的结构区分开。请与产线运行良好时的数据比较（“与参考期比较”），或记录更长、更多的批次。</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="294"/>
        <source>Next: nothing in the model needs changing for these data. To see smaller effects, record longer or more batches.</source>
        <translation>下一步：对这些数据，模型无需修改。若要看出更小的影响，请记录更长时间或更多批次。</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="299"/>
        <source>Next: compare with data from a time when the line ran well (“Compare with a reference period”): what changed since then is named more surely than from one data set alone. The evidence says which measurement the error follows; check that transmitter and the maintenance log around the time it starts.</source>
        <translation>下一步：与产线运行良好时的数据比较（“与参考期比较”）：与单个数据集相比，能更可靠地指出此后发生的变化。证据说明了误差跟随哪个测量值；请检查该变送器以及误差开始前后的维护记录。</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="312"/>
        <source>Completed</source>
        <translation>已完成</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="314"/>
        <source>Converged</source>
        <translation>已收敛</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="316"/>
        <source>Evaluation budget used up</source>
        <translation>评估次数已用完</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="318"/>
        <source>Stopped by you, best so far kept</source>
        <translation>已由您停止，保留目前最优</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="325"/>
        <source>Stopped by you; the runs so far are kept, the last one is partial</source>
        <translation>已由您停止；保留已完成的运行，最后一次不完整</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="332"/>
        <source>Scenario %1: %2 of %3 controllers run over %4 scored seconds</source>
        <translation>情景 %1：%3 个控制器中运行了 %2 个，评分时长 %4 秒</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="342"/>
        <source>none (the sensitivities could not be computed)</source>
        <translation>无（无法计算灵敏度）</translation>
    </message>
    <message>
        <source>widened because neighbouring rows are alike and not independent evidence (sandwich covariance with a Newey-West middle term)</source>
        <translation>已加宽：相邻样本彼此相似，不是独立的证据（夹心协方差，中间项为 Newey-West）</translation>
    </message>
    <message>
        <source>robust to correlated rows (sandwich covariance with a Newey-West middle term)</source>
        <translation>对相关样本稳健（夹心协方差，中间项为 Newey-West）</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="362"/>
        <source>R² could not be computed (too few rows).</source>
        <translation>无法计算 R²（行数太少）。</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="365"/>
        <source>R² below 0: the model predicts worse than the batch&apos;s mean would. Usual for the physics model alone on a short held-out part with little movement; compare MAE instead.</source>
        <translation>R² 小于 0：模型的预测比批次均值还差。对于变化很小的短留出段，单独的物理模型常出现这种情况；请改为比较 MAE。</translation>
    </message>
    <message>
        <location filename="../widgets/common/DisplayNames.cpp" line="370"/>
        <source>R² %1: the model explains %2 % of the variation of the measured values about their mean.</source>
        <translation>R² %1：模型解释了测量值围绕其均值变化的 %2 %。</translation>
    </message>
</context>
<context>
    <name>EngineText</name>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="48"/>
        <source>%1: column &apos;%2&apos; holds text; it is not kept in the runs</source>
        <translation>%1：列“%2”为文本，不保留在生产批次中</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="50"/>
        <source>%1: a run of %2 s is shorter than the minimum of %3 s; left out</source>
        <translation>%1：一段 %2 s 的运行短于最短 %3 s，已略去</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="54"/>
        <source>%1: rows are typically %2 s apart, not the 1 s the model and the learnt layer&apos;s lags assume; the physics follows the time stamps, the lags and horizons count rows</source>
        <translation>%1：行间隔通常为 %2 s，而不是模型和学习层滞后所假设的 1 s；物理模型按时间戳计算，滞后和预测步长按行计数</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="61"/>
        <source>%1, line %2: a gap of %3 s in time (rows typically %4 s apart): the model runs across it as if the line had run on; a stop is better cut into two batches</source>
        <translation>%1，第 %2 行：时间上有 %3 s 的间隔（行间隔通常为 %4 s）：模型会当作产线持续运行一样跨过它；停机最好分成两个批次</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="68"/>
        <source>%1: column %2: %3 cell(s) hold PI digital states (%4), the first here; read as missing values</source>
        <translation>%1：列 %2：%3 个单元格为 PI 数字状态（%4），第一个在此处；按缺失值读取</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="72"/>
        <source>%1: lines end in a carriage return alone (classic Mac OS); read as lines</source>
        <translation>%1：行仅以回车符结尾（经典 Mac OS）；已按行读取</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="81"/>
        <source>%1: a tag/value export (one row per tag and time stamp: columns &apos;%2&apos;, &apos;%3&apos;, &apos;%4&apos;), read as one column per tag: %5 tags over %6 time stamps; %7 cells where a tag has no sample at a stamp hold its last sample (at most %8 s back), %9 are left empty; places in later messages count rows of that table</source>
        <translation>%1：位号/数值格式的导出（每个位号和时间戳一行：列“%2”、“%3”、“%4”），已按每个位号一列读取：%5 个位号，%6 个时间戳；%7 个在该时间戳无采样的单元格沿用该位号上一次的采样（最多回溯 %8 s），%9 个留空；后续消息中的位置按该表的行计数</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="89"/>
        <source>%1: %2 rows repeat a tag at a time stamp already read; the later value is kept</source>
        <translation>%1：%2 行在已读过的时间戳上重复了某个位号；保留后出现的值</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="94"/>
        <source>%1: %2 reads %3 %4 on average, the other batches about %5 (their median): this batch in another unit (°F, K, a fraction, t/h) or another column? Check it</source>
        <translation>%1：%2 平均读数为 %3 %4，其他批次约为 %5（中位数）：该批次是否用了另一单位（°F、K、分数、t/h）或另一列？请检查</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="111"/>
        <source>no measurement of the outlet moisture at this step</source>
        <translation>此步没有出口含水率的测量值</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="113"/>
        <source>the forecast was too short</source>
        <translation>预测太短</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="115"/>
        <source>the forecast was not finite (missing history or inputs)</source>
        <translation>预测不是有限值（缺少历史数据或输入）</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="117"/>
        <source>the model shows no effect of the hot air on the outlet moisture</source>
        <translation>模型中热风对出口含水率没有作用</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="119"/>
        <source>the forecast failed: %1</source>
        <translation>预测失败：%1</translation>
    </message>
    <message>
        <location filename="../widgets/common/EngineText.cpp" line="121"/>
        <source>the optimiser (Ipopt) stopped: %1</source>
        <translation>优化器（Ipopt）停止：%1</translation>
    </message>
</context>
<context>
    <name>FaultWords</name>
    <message>
        <location filename="../widgets/training/FaultWords.cpp" line="23"/>
        <source>NTU (wall loss)</source>
        <translation>NTU（管壁散热）</translation>
    </message>
    <message>
        <location filename="../widgets/training/FaultWords.cpp" line="25"/>
        <source>× full air-side coupling</source>
        <translation>× 完全气相耦合</translation>
    </message>
    <message>
        <location filename="../widgets/training/FaultWords.cpp" line="27"/>
        <source>of h_HDT lost</source>
        <translation>的 h_HDT 损失</translation>
    </message>
    <message>
        <location filename="../widgets/training/FaultWords.cpp" line="29"/>
        <source>of the drying rate lost</source>
        <translation>的干燥速率损失</translation>
    </message>
    <message>
        <location filename="../widgets/training/FaultWords.cpp" line="42"/>
        <source>The virtual plant&apos;s own, richer form of this cause: Discover fits the model&apos;s simpler form of it, with a parameter of its own (its unit may differ, e.g. fouling in 1/h), so the two numbers are not the same quantity.</source>
        <translation>这是虚拟装置中该原因自身更丰富的形式：“发现”拟合的是模型中该原因更简单的形式，参数不同（单位也可能不同，例如结垢为 1/h），因此两个数值不是同一个量。</translation>
    </message>
    <message>
        <location filename="../widgets/training/FaultWords.cpp" line="51"/>
        <source>not acting yet</source>
        <translation>尚未起作用</translation>
    </message>
    <message>
        <location filename="../widgets/training/FaultWords.cpp" line="54"/>
        <source>found after %1 s</source>
        <translation>%1 s 后发现</translation>
    </message>
    <message>
        <location filename="../widgets/training/FaultWords.cpp" line="58"/>
        <source>time to react: %1 min left</source>
        <translation>反应时间：还剩 %1 分钟</translation>
    </message>
    <message>
        <location filename="../widgets/training/FaultWords.cpp" line="61"/>
        <source>not found</source>
        <translation>未发现</translation>
    </message>
    <message>
        <location filename="../widgets/training/FaultWords.cpp" line="70"/>
        <source>&lt;b&gt;Score %1 / 100&lt;/b&gt; — faults found %2 of %3, wrong answers %4, product out of the band %5 % of the time (%6 kg)</source>
        <translation>&lt;b&gt;得分 %1 / 100&lt;/b&gt; — 找到故障 %2 / %3，错误回答 %4，产品超出允许带的时间占 %5 %（%6 kg）</translation>
    </message>
    <message>
        <location filename="../widgets/training/FaultWords.cpp" line="81"/>
        <source>; %1 fault(s) within the trainee&apos;s %2 minutes to react, not scored yet</source>
        <translation>；%1 个故障仍在学员 %2 分钟的反应时间内，尚未计分</translation>
    </message>
</context>
<context>
    <name>ParameterTexts</name>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="16"/>
        <source>ideal gas constant</source>
        <translation>理想气体常数</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="17"/>
        <source>specific gas constant of water vapour</source>
        <translation>水蒸气比气体常数</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="18"/>
        <source>specific heat of dry material</source>
        <translation>干物料比热容</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="19"/>
        <source>specific heat of water</source>
        <translation>水的比热容</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="20"/>
        <source>temperature parameter of water activity (Eq. 2)</source>
        <translation>水分活度的温度参数（公式 2）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="21"/>
        <source>Oswin parameter 1 (Eq. 5)</source>
        <translation>Oswin 参数 1（公式 5）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="22"/>
        <source>Oswin parameter 2 (Eq. 5), per kelvin of T in °C</source>
        <translation>Oswin 参数 2（公式 5），T 以 °C 计时每开尔文</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="23"/>
        <source>Oswin parameter 3 (Eq. 5)</source>
        <translation>Oswin 参数 3（公式 5）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="24"/>
        <source>diffusivity pre-factor (Eq. 6)</source>
        <translation>扩散系数指前因子（公式 6）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="25"/>
        <source>activation energy of diffusion (Eq. 6)</source>
        <translation>扩散活化能（公式 6）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="26"/>
        <source>bound-water latent heat correction (Eq. 4)</source>
        <translation>结合水潜热修正（公式 4）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="27"/>
        <source>humidity reduction of diffusivity (Eq. 6)</source>
        <translation>湿度对扩散系数的降低（公式 6）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="28"/>
        <source>particle density of the material (Eq. 7)</source>
        <translation>物料颗粒密度（公式 7）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="29"/>
        <source>strand radius as a cylinder (Eq. 7)</source>
        <translation>按圆柱计的丝条半径（公式 7）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="30"/>
        <source>strand length (Eq. 7)</source>
        <translation>丝条长度（公式 7）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="31"/>
        <source>convective heat-transfer coefficient in the tube (Eq. 8)</source>
        <translation>管内对流传热系数（公式 8）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="32"/>
        <source>mass-transfer coefficient in the tube (Eq. 10)</source>
        <translation>管内传质系数（公式 10）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="33"/>
        <source>humidity ratio of the drying air (Eq. 9)</source>
        <translation>干燥风的含湿量（公式 9）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="34"/>
        <source>total pressure of the drying air (Eq. 9)</source>
        <translation>干燥风总压（公式 9）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="35"/>
        <source>enthalpy reference temperature (Eqs. 12, 14, 19)</source>
        <translation>焓的参考温度（公式 12、14、19）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="36"/>
        <source>layer packing factor (Eq. 13)</source>
        <translation>料层堆积系数（公式 13）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="37"/>
        <source>characteristic diffusion length (Eq. 13)</source>
        <translation>特征扩散长度（公式 13）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="38"/>
        <source>natural-convection coefficient on the belt (Eq. 14)</source>
        <translation>输送带上的自然对流系数（公式 14）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="39"/>
        <source>exposed area per kg of dry matter on the belt (Eq. 14)</source>
        <translation>输送带上每千克干物质的暴露面积（公式 14）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="40"/>
        <source>mass fraction of the conveyor top layer (Eqs. 15-16)</source>
        <translation>输送机表层的质量分数（公式 15–16）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="41"/>
        <source>flash-evaporation rate in the winnower (Eqs. 17-18)</source>
        <translation>风选机内的闪蒸速率（公式 17–18）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="42"/>
        <source>heat loss of the winnower per kg of dry matter (Eq. 19)</source>
        <translation>风选机每千克干物质的散热（公式 19）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="43"/>
        <source>residence time in the winnower (Eqs. 17-19)</source>
        <translation>风选机内停留时间（公式 17–19）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="44"/>
        <source>residence time in the drying tube</source>
        <translation>干燥管内停留时间</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="45"/>
        <source>transport time on the conveyor</source>
        <translation>输送机上的输送时间</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="46"/>
        <source>time constant of the hot-air temperature actuator</source>
        <translation>热风温度执行机构的时间常数</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="47"/>
        <source>outlet mixing: first-order lag of X_out and T_out (belt and winnower holdup)</source>
        <translation>出口混合：X_out 和 T_out 的一阶滞后（输送带和风选机存料）</translation>
    </message>
    <message>
        <source>tube wall heat loss: T_gas = T_hot - theta (T_hot - T_amb)</source>
        <translation type="vanished">管壁散热：T_gas = T_hot - theta (T_hot - T_amb)</translation>
    </message>
    <message>
        <source>gas-phase coupling: T_gas falls by theta L_v (X_in - X) m_dry / (c_air m_air) along the tube</source>
        <translation type="vanished">气相耦合：沿管 T_gas 降低 theta L_v (X_in - X) m_dry / (c_air m_air)</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="49"/>
        <source>tube wall heat loss, its transfer units over the tube: T_gas = T_amb + (T_hot - T_amb) exp(-theta s / tau_HDT)</source>
        <translation>管壁散热，整根管的传热单元数：T_gas = T_amb + (T_hot - T_amb) exp(-theta s / tau_HDT)</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="51"/>
        <source>gas-phase coupling: T_gas falls by theta L_v (X_in - X) m_dry / (c_air m_air) along the tube, and w rises by theta (X_in - X) m_dry / m_air</source>
        <translation>气相耦合：沿管 T_gas 降低 theta L_v (X_in - X) m_dry / (c_air m_air)，w 升高 theta (X_in - X) m_dry / m_air</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="55"/>
        <source>fouling: h = h_HDT (1 - theta t), t since the batch started</source>
        <translation>结垢：h = h_HDT (1 - theta t)，t 为批次开始后的时间</translation>
    </message>
    <message>
        <source>fouling: h = h_HDT / (1 + theta t), a deposit&apos;s resistance growing since the batch started</source>
        <translation type="vanished">结垢：h = h_HDT / (1 + theta t)，垢层热阻自批次开始起随时间增长</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="56"/>
        <source>first-order lag of the outlet moisture meter</source>
        <translation>出口水分仪的一阶滞后</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="57"/>
        <source>constant offset of the outlet moisture meter</source>
        <translation>出口水分仪的恒定偏差</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="58"/>
        <source>conveyor transport time minus tau_conv</source>
        <translation>输送时间减去 tau_conv</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="59"/>
        <source>falling-rate drying: Eq. 10 times 1 - theta (X_cr - X)/X_cr below X_cr = 0.25 kg/kg</source>
        <translation>降速干燥：低于 X_cr = 0.25 kg/kg 时公式 10 乘以 1 - theta (X_cr - X)/X_cr</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="61"/>
        <source>re-absorption on the conveyor: dX/dt gains theta RH</source>
        <translation>输送机上的回潮：dX/dt 增加 theta RH</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="62"/>
        <source>offset of the inlet moisture gauge: the line sees X_in measured minus it</source>
        <translation>入口水分仪偏差：产线实际含水率为 X_in 测量值减去它</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="64"/>
        <source>time constant of the hot-air sensor: the line sees T_hot + tau dT_hot/dt (its inverse lag)</source>
        <translation>热风传感器时间常数：产线实际为 T_hot + tau dT_hot/dt（其逆滞后）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="67"/>
        <source>share of the inlet gauge&apos;s fast variation (about its 20 s zero-phase mean) that is scatter, not moisture: the line sees X_in with that share removed</source>
        <translation>入口水分仪快速变化（相对其 20 s 零相位均值）中属于仪表波动而非真实水分的比例：产线实际为去掉这一部分的 X_in</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="70"/>
        <source>onset of the mechanism extensions since each batch&apos;s start (0: from the start; transport_delay_error always acts from the start)</source>
        <translation>机理扩展自各批次开始起的起始时间（0：从开始；transport_delay_error 总是从开始起作用）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="72"/>
        <source>paper App. A</source>
        <translation>论文附录 A</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="73"/>
        <source>paper App. A (bounds: sign kept, tenfold range)</source>
        <translation>论文附录 A（范围：保持符号，十倍区间）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="74"/>
        <source>gives D_eff ≈ 1.7e-10 m²/s at 57 °C, the order reported for tobacco lamina</source>
        <translation>在 57 °C 时 D_eff ≈ 1.7e-10 m²/s，与烟叶文献报道的量级一致</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="76"/>
        <source>typical of leaf materials (20–40 kJ/mol)</source>
        <translation>叶类物料的典型值（20–40 kJ/mol）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="77"/>
        <source>heat of sorption of tobacco adds up to about a third near dryness</source>
        <translation>接近干燥时烟草的吸附热可增加约三分之一</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="78"/>
        <source>humid air halves the surface gradient at saturation</source>
        <translation>饱和时湿空气使表面梯度减半</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="79"/>
        <source>cut tobacco strands (lamina with air spaces)</source>
        <translation>烟丝（含气隙的叶片）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="80"/>
        <source>cut width about 1 mm</source>
        <translation>切丝宽度约 1 mm</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="81"/>
        <source>cut tobacco strands of 1–3 cm</source>
        <translation>长 1–3 cm 的烟丝</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="82"/>
        <source>paper §IV.C calibrated value</source>
        <translation>论文 §IV.C 标定值</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="83"/>
        <source>recirculated hot air of a tobacco dryer is humid</source>
        <translation>烟草干燥机的循环热风较湿</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="84"/>
        <source>atmospheric</source>
        <translation>大气压</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="85"/>
        <source>0 °C, the reference of the 2501 kJ/kg in Eq. 4</source>
        <translation>0 °C，即公式 4 中 2501 kJ/kg 的参考温度</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="86"/>
        <source>loose single layer</source>
        <translation>松散单层</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="87"/>
        <source>gives about 1 % dry-basis loss of the top layer on a 60 s belt</source>
        <translation>在 60 s 的输送带上表层约损失 1 %（干基）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="88"/>
        <source>natural convection of a horizontal layer</source>
        <translation>水平料层的自然对流</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="89"/>
        <source>top layer of about 2 kg/m²</source>
        <translation>表层约 2 kg/m²</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="90"/>
        <source>top third of the layer exchanges with the air</source>
        <translation>料层上部三分之一与空气交换</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="91"/>
        <source>about 0.4 % wb flash loss at 35 K excess temperature</source>
        <translation>过热 35 K 时约 0.4 %（湿基）的闪蒸损失</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="92"/>
        <source>turbulent air, short contact</source>
        <translation>湍流空气，接触时间短</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="93"/>
        <source>a few seconds</source>
        <translation>几秒</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="94"/>
        <source>tube of about 70 m at 10 m/s particle speed</source>
        <translation>管长约 70 m，颗粒速度 10 m/s</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="95"/>
        <source>belt of 12 m at 0.2 m/s</source>
        <translation>输送带长 12 m，速度 0.2 m/s</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="96"/>
        <source>heat exchanger and duct lag; used when T_hot follows its setpoint (MPC)</source>
        <translation>换热器和风道的滞后；用于 T_hot 跟随设定值时（MPC）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="98"/>
        <source>distributed line: axial mixing on the belt, the winnower&apos;s stirred volume</source>
        <translation>分布式产线：输送带上的轴向混合、风选机的搅拌容积</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="100"/>
        <source>extension tube_wall_heat_loss</source>
        <translation>扩展 tube_wall_heat_loss</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="101"/>
        <source>extension gas_phase_coupling</source>
        <translation>扩展 gas_phase_coupling</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="102"/>
        <source>extension heat_transfer_fouling</source>
        <translation>扩展 heat_transfer_fouling</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="103"/>
        <source>extension moisture_meter_lag</source>
        <translation>扩展 moisture_meter_lag</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="104"/>
        <source>extension moisture_meter_offset</source>
        <translation>扩展 moisture_meter_offset</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="105"/>
        <source>extension transport_delay_error</source>
        <translation>扩展 transport_delay_error</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="106"/>
        <source>extension falling_rate_drying</source>
        <translation>扩展 falling_rate_drying</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="107"/>
        <source>extension ambient_reabsorption</source>
        <translation>扩展 ambient_reabsorption</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="108"/>
        <source>extension inlet_moisture_sensor_offset</source>
        <translation>扩展 inlet_moisture_sensor_offset</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="109"/>
        <source>extension hot_air_sensor_lag</source>
        <translation>扩展 hot_air_sensor_lag</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="110"/>
        <source>extension inlet_moisture_sensor_noise</source>
        <translation>扩展 inlet_moisture_sensor_noise</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="111"/>
        <source>set by discovery for a cause that starts mid-batch</source>
        <translation>由发现功能为批次中途出现的原因设定</translation>
    </message>
    <message>
        <location filename="../widgets/model/ParameterTexts.cpp" line="130"/>
        <source>added for the cause: %1</source>
        <translation>为原因“%1”添加</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="34"/>
        <source>set %1 to %2</source>
        <translation>将 %1 设为 %2</translation>
    </message>
</context>
<context>
    <name>ResidualPanel</name>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="387"/>
        <source>PGRL-CC, all components</source>
        <translation>PGRL-CC，全部组成部分</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="388"/>
        <source>1. no a_w clamping</source>
        <translation>1. 不截断 a_w</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="389"/>
        <source>2. no L_v correction</source>
        <translation>2. 不修正 L_v</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="390"/>
        <source>3. no C_p(X) dependency</source>
        <translation>3. C_p 不随 X 变化</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="392"/>
        <source>E. energy balance as printed (Eqs. 12, 14, 19 count C_p,w (T - T_ref) twice)</source>
        <translation>E. 按论文原式的能量平衡（式 12、14、19 将 C_p,w (T - T_ref) 计了两次）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="395"/>
        <source>E. consistent energy balance (L_v only)</source>
        <translation>E. 自洽的能量平衡（仅 L_v）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="397"/>
        <source>4. no orthogonal learning (P_perp)</source>
        <translation>4. 不做正交学习（P_perp）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="399"/>
        <source>4. with orthogonal learning (P_perp, Eq. 27; the trained model has none)</source>
        <translation>4. 加正交学习（P_perp，式 27；已训练的模型未使用）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="402"/>
        <source>4b. Eq. 27 read literally (base part of e dropped from the prediction)</source>
        <translation>4b. 按字面理解式 27（预测中去掉 e 的基础部分）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="404"/>
        <source>5. no control-consistent weights</source>
        <translation>5. 不用控制一致权重</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="406"/>
        <source>6. no stability constraint (EDMDc-S)</source>
        <translation>6. 无稳定性约束（EDMDc-S）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="408"/>
        <source>6b. eigenvalues pulled in after an unconstrained fit instead of Eq. 30</source>
        <translation>6b. 无约束拟合后收缩特征值，代替式 30</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="411"/>
        <source>7. the paper&apos;s lifted model of e itself (the trivial predictors not nested)</source>
        <translation>7. 论文对 e 本身的提升模型（不嵌套平凡预测）</translation>
    </message>
</context>
<context>
    <name>ScenarioForm</name>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="42"/>
        <source>feed [kg/h]</source>
        <translation>进料 [kg/h]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="43"/>
        <source>inlet moisture [% wb]</source>
        <translation>入口含水率 [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="44"/>
        <source>ambient temperature [°C]</source>
        <translation>环境温度 [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="45"/>
        <source>ambient humidity [% RH]</source>
        <translation>环境湿度 [% RH]</translation>
    </message>
</context>
<context>
    <name>StaleReason</name>
    <message>
        <location filename="../widgets/common/Workbench.h" line="24"/>
        <source>the physics model was calibrated after it was learnt</source>
        <translation>学习之后物理模型又经过了标定</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.h" line="26"/>
        <source>the model was extended by discovery</source>
        <translation>模型已由发现功能扩展</translation>
    </message>
</context>
<context>
    <name>TrainingPanel</name>
    <message>
        <source>PI loop (the plant&apos;s own)</source>
        <translation>PI 回路（装置自带）</translation>
    </message>
    <message>
        <source>MPC on the physics model</source>
        <translation>基于物理模型的 MPC</translation>
    </message>
    <message>
        <source>MPC on PGRL-CC</source>
        <translation>基于 PGRL-CC 的 MPC</translation>
    </message>
    <message>
        <source>MPC on the external-input residual model</source>
        <translation>基于外部输入残差模型的 MPC</translation>
    </message>
    <message>
        <source>MPC on the LSTM</source>
        <translation>基于 LSTM 的 MPC</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelInternal.h" line="32"/>
        <source>MPC on: %1</source>
        <translation>MPC，基于：%1</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelInternal.h" line="80"/>
        <source>It was saved with another model (fingerprint %1, this one %2): its MPC controllers (%3) run on this one, so the recording may differ from the saved one. Open the project or model file it was run with to replay it exactly.</source>
        <translation>该会话是用另一个模型保存的（指纹 %1，当前模型 %2）：其 MPC 控制器（%3）现在运行在当前模型上，因此记录可能与保存的不同。要精确重放，请打开当时使用的项目或模型文件。</translation>
    </message>
    <message>
        <source>Tube wall heat loss</source>
        <translation>管壁散热损失</translation>
    </message>
    <message>
        <source>Gas-phase coupling</source>
        <translation>气相耦合</translation>
    </message>
    <message>
        <source>Heat-transfer fouling</source>
        <translation>传热结垢</translation>
    </message>
    <message>
        <source>Moisture meter lag</source>
        <translation>水分仪滞后</translation>
    </message>
    <message>
        <source>Moisture meter offset</source>
        <translation>水分仪偏差</translation>
    </message>
    <message>
        <source>Transport delay error</source>
        <translation>输送延时误差</translation>
    </message>
    <message>
        <source>Falling-rate drying</source>
        <translation>降速干燥</translation>
    </message>
    <message>
        <source>Ambient re-absorption</source>
        <translation>环境回潮</translation>
    </message>
    <message>
        <source>Inlet moisture gauge offset</source>
        <translation>入口水分仪零点偏移</translation>
    </message>
    <message>
        <source>Hot-air thermocouple lag</source>
        <translation>热风热电偶滞后</translation>
    </message>
    <message>
        <source>Inlet moisture gauge scatter</source>
        <translation>入口水分仪读数离散</translation>
    </message>
</context>
<context>
    <name>TrainingRunner</name>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="38"/>
        <location filename="../widgets/training/TrainingRunner.cpp" line="43"/>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="52"/>
        <location filename="../widgets/training/TrainingRunner.cpp" line="59"/>
        <source>Open session</source>
        <translation>打开会话</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="71"/>
        <location filename="../widgets/training/TrainingRunner.cpp" line="103"/>
        <source>Start a session first.</source>
        <translation>请先开始一个会话。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="102"/>
        <location filename="../widgets/training/TrainingRunner.cpp" line="111"/>
        <location filename="../widgets/training/TrainingRunner.cpp" line="126"/>
        <location filename="../widgets/training/TrainingRunner.cpp" line="218"/>
        <source>Save session</source>
        <translation>保存会话</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::CalibrationPanel</name>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="32"/>
        <source>Free</source>
        <translation>自由</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="32"/>
        <source>Lower</source>
        <translation>下限</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="32"/>
        <source>Upper</source>
        <translation>上限</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="32"/>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="68"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="64"/>
        <source> evaluations</source>
        <translation> 次评估</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="65"/>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="201"/>
        <source>Calibrate</source>
        <translation>标定</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="66"/>
        <source>Stop, keep best</source>
        <translation>停止并保留最优</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="68"/>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="68"/>
        <source>Estimate</source>
        <translation>估计值</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="68"/>
        <source>95 % interval</source>
        <translation>95 % 区间</translation>
    </message>
    <message>
        <source>Fisher SE</source>
        <translation>Fisher 标准误</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="69"/>
        <source>At bound</source>
        <translation>触及边界</translation>
    </message>
    <message>
        <source>Fits the free parameters to the calibration rows (every 10th kept row, the first 300) with NLopt: a global search, then BOBYQA.</source>
        <translation>用 NLopt 将自由参数拟合到标定行（保留行中每隔 10 行取一行，取前 300 行）：先全局搜索，再用 BOBYQA。</translation>
    </message>
    <message>
        <source>Fits the free parameters to the calibration rows (every 10th kept row, the first 300) with NLopt: a global search, then a local polish that needs no derivatives (BOBYQA).</source>
        <translation>用 NLopt 将自由参数拟合到标定样本（保留样本每 10 行取 1 行，取前 300 行）：先全局搜索，再做无需导数的局部精修（BOBYQA）。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="69"/>
        <source>Standard
error</source>
        <translation>标准
误差</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="71"/>
        <source>Fits the free parameters to the calibration rows (every 10th kept row, the first 300): a global search, then a local polish that needs no derivatives.</source>
        <translation>将自由参数拟合到标定样本（保留样本每 10 行取 1 行，取前 300 行）：先全局搜索，再做无需导数的局部精修。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="73"/>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="258"/>
        <source>NLopt: CRS2-LM for the global search, then BOBYQA for the local polish.</source>
        <translation>NLopt：全局搜索用 CRS2-LM，局部精修用 BOBYQA。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="77"/>
        <source>The parameter&apos;s symbol; hover over a name for its meaning.</source>
        <translation>参数符号；将鼠标停在名称上可看其含义。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="77"/>
        <source>The fitted value.</source>
        <translation>拟合值。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="78"/>
        <source>The range that holds the true value with 95 % confidence, given the data.</source>
        <translation>在现有数据下以 95 % 置信度包含真值的范围。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="79"/>
        <source>Fisher SE: the estimate&apos;s standard error from the fit&apos;s curvature (the Fisher information); about a third of the 95 % interval&apos;s width.</source>
        <translation>Fisher 标准误：由拟合曲面的曲率（Fisher 信息）得到的估计标准误差；约为 95 % 区间宽度的三分之一。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="81"/>
        <source>At bound: the fit stopped at the edge of the search range; widen the bounds or suspect the model.</source>
        <translation>触及边界：拟合停在搜索范围的边缘；请放宽边界，或怀疑模型本身。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="84"/>
        <source>best loss [-]</source>
        <translation>最优损失 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="85"/>
        <source>θ / θ final [-]</source>
        <translation>θ / θ 最终值 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="86"/>
        <source>share of the evaluation budget used [-]</source>
        <translation>已用评估预算比例 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="90"/>
        <source>Free parameters and their search bounds:</source>
        <translation>自由参数及其搜索范围：</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="104"/>
        <source>X_out [% wb]</source>
        <translation>X_out [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="130"/>
        <source>best loss so far</source>
        <translation>迄今最优损失</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="149"/>
        <source>Run Calibrate to see the loss fall and the parameters settle</source>
        <translation>运行标定，可看到损失下降、参数收敛</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="154"/>
        <source>The parameters&apos; paths are drawn when the calibration ends</source>
        <translation>标定结束后绘出各参数的变化轨迹</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="155"/>
        <source>Run Calibrate to see the fit before and after</source>
        <translation>运行标定，可看到标定前后的拟合</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="197"/>
        <source>Cannot calibrate: %1</source>
        <translation>无法标定：%1</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="207"/>
        <source>Calibrating…</source>
        <translation>正在标定…</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="233"/>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="233"/>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="242"/>
        <source>On %1: </source>
        <translation>数据 %1：</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="243"/>
        <source>%1 after %2 evaluations (%3 s). Loss %4 → %5; on its %11 calibration rows the MAE of the outlet moisture %6 → %7 % wb, of the outlet temperature %8 → %9 °C. Intervals: %10.</source>
        <translation>%2 次评估后%1（%3 s）。损失 %4 → %5；在其 %11 个标定样本上，出口含水率的 MAE %6 → %7 % 湿基，出口温度的 MAE %8 → %9 °C。区间：%10。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="319"/>
        <source>On all %1 kept rows the outlet moisture&apos;s MAE %2 → %3 % wb (the status bar&apos;s figure).</source>
        <translation>在全部 %1 个保留样本上，出口含水率的 MAE %2 → %3 % 湿基（即状态栏的数值）。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="323"/>
        <source>On all %1 kept rows the outlet moisture&apos;s MAE is now %2 % wb (the status bar&apos;s figure).</source>
        <translation>在全部 %1 个保留样本上，出口含水率的 MAE 现为 %2 % 湿基（即状态栏的数值）。</translation>
    </message>
    <message>
        <source>%1 after %2 evaluations (%3 s). Loss %4 → %5; MAE of the outlet moisture %6 → %7 % wb, of the outlet temperature %8 → %9 °C. Intervals: %10.</source>
        <translation>%1，共 %2 次评估（%3 s）。损失 %4 → %5；出口水分 MAE %6 → %7 % 湿基，出口温度 MAE %8 → %9 °C。区间：%10。</translation>
    </message>
    <message>
        <source>%1 after %2 evaluations (%3 s). Loss %4 → %5; outlet MAE %6 → %7 % wb, %8 → %9 °C. Intervals: %10.</source>
        <translation type="vanished">%1，共 %2 次评估（%3 s）。损失 %4 → %5；出口 MAE %6 → %7 % 湿基，%8 → %9 °C。区间：%10。</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="272"/>
        <source>loss evaluations [-]</source>
        <translation>损失评估次数 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="273"/>
        <source>best loss</source>
        <translation>最优损失</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="307"/>
        <source>measured %1</source>
        <translation>实测 %1</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="310"/>
        <source>before</source>
        <translation>之前</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="313"/>
        <source>after</source>
        <translation>之后</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::ColumnMappingDialog</name>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="35"/>
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
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="49"/>
        <source>Delimiter %1, %2, time stamps in column &apos;%3&apos; (%4)%5.</source>
        <translation>分隔符 %1，%2，时间戳在列“%3”中（%4）%5。</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="50"/>
        <source>tab</source>
        <translation>制表符</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="51"/>
        <source>decimal commas</source>
        <translation>小数逗号</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="51"/>
        <source>decimal points</source>
        <translation>小数点</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="54"/>
        <source>, a units row under the header</source>
        <translation>，表头下有单位行</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="57"/>
        <source>Could not read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="58"/>
        <source>Choose, for each column DryTwin needs, the header your files use and the unit its values are in (converted when read); required columns are marked *. The proposal comes from the headers&apos; words and tag letters and the ranges of the first rows&apos; values: check it.</source>
        <translation>为 DryTwin 需要的每一列选择您文件中使用的表头及其数值的单位（读取时换算）；必需的列标有 *。建议来自表头中的词语、位号字母以及前几行数值的范围：请核对。</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="66"/>
        <source>DryTwin column</source>
        <translation>DryTwin 列</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="66"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="66"/>
        <source>Header in your file</source>
        <translation>您文件中的表头</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="67"/>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="67"/>
        <source>Unit in your file</source>
        <translation>您文件中的单位</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="67"/>
        <source>Why proposed</source>
        <translation>建议依据</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="80"/>
        <source>(not in the file)</source>
        <translation>（文件中没有）</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="123"/>
        <source>(none: cut runs at line stops and gaps)</source>
        <translation>（无：在停线和时间间断处切分生产段）</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="130"/>
        <source>Column that names the production run:</source>
        <translation>标识生产段的列：</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="135"/>
        <source>Run</source>
        <translation>生产段</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="135"/>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="135"/>
        <source>File lines</source>
        <translation>文件行</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="135"/>
        <source>Rows</source>
        <translation>行数</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="135"/>
        <source>Interpolated cells</source>
        <translation>插值单元格</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="135"/>
        <source>Ended by</source>
        <translation>结束原因</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="149"/>
        <source>Proposed as you mapped a file with these same headers before; check it.</source>
        <translation>按您以前对相同表头文件的映射提出；请检查。</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="202"/>
        <source>as you mapped these headers before</source>
        <translation>按您以前对这些表头的映射</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="222"/>
        <source>The mapping is not complete: %1</source>
        <translation>映射不完整：%1</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="228"/>
        <source>With this mapping the file does not load: %1</source>
        <translation>按此映射无法加载该文件：%1</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="234"/>
        <source>The first %1 MB of the file give these production runs:</source>
        <translation>文件前 %1 MB 给出以下生产段：</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="235"/>
        <source>The file gives these production runs:</source>
        <translation>该文件给出以下生产段：</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="237"/>
        <source>Notes while reading: %1; the first: %2</source>
        <translation>读取时的提示：%1 条；第一条：%2</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="250"/>
        <source>one batch</source>
        <translation>单个批次</translation>
    </message>
    <message>
        <location filename="../widgets/data/ColumnMappingDialog.cpp" line="334"/>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::DataPanel</name>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="46"/>
        <source>Open file…</source>
        <translation>打开文件…</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="47"/>
        <source>Open folder…</source>
        <translation>打开文件夹…</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="48"/>
        <source>Column mapping…</source>
        <translation>列映射…</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="49"/>
        <source>Files with other column names: map them onto DryTwin&apos;s columns, then load</source>
        <translation>列名不同的文件：先映射到 DryTwin 的列，再加载</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="53"/>
        <source>Batches overlaid</source>
        <translation>批次叠加</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="53"/>
        <source>Batches one after another</source>
        <translation>批次首尾相接</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="54"/>
        <source>Batch</source>
        <translation>批次</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="54"/>
        <source>Rows</source>
        <translation>行数</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="54"/>
        <source>Kept</source>
        <translation>保留</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="54"/>
        <source>Length [min]</source>
        <translation>时长 [min]</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="55"/>
        <source>Mean X_out [% wb]</source>
        <translation>平均 X_out [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="55"/>
        <source>Mean T_hot [°C]</source>
        <translation>平均 T_hot [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="55"/>
        <source>Source</source>
        <translation>来源</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="70"/>
        <source>Batches (select several to overlay; drop files here):</source>
        <translation>批次（多选可叠加；可将文件拖放到此处）：</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="89"/>
        <source>Open batch file</source>
        <translation>打开批次文件</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="89"/>
        <location filename="../widgets/data/DataPanel.cpp" line="102"/>
        <source>Batch files (*.csv)</source>
        <translation>批次文件 (*.csv)</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="95"/>
        <source>Open data set folder</source>
        <translation>打开数据集文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="102"/>
        <source>A batch file with your column names</source>
        <translation>一个使用您的列名的批次文件</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="111"/>
        <source>Open a data set: File ▸ Open data set folder…, or File ▸ Open the bundled demo</source>
        <translation>请打开数据集：文件 ▸ 打开数据集文件夹…，或 文件 ▸ 打开自带演示数据</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="134"/>
        <source>Save the column mapping</source>
        <translation>保存列映射</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="135"/>
        <source>Mappings (*.json)</source>
        <translation>映射 (*.json)</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="146"/>
        <source>The column mapping could not be saved (%1); the data were not loaded.</source>
        <translation>列映射无法保存（%1）；数据未载入。</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="155"/>
        <source>The column mapping is kept at %1 and in the project when you save it; “Column mapping…” changes it.</source>
        <translation>列映射保存在 %1，保存项目时也会存入项目；用“列映射…”可以修改。</translation>
    </message>
    <message>
        <source>The column mapping is kept at %1 and in the project when you save it; “Map its columns…” changes it.</source>
        <translation>列映射已保存在 %1，保存项目时也会一并保存；可用“映射其列…”修改。</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="213"/>
        <source>%1, lines %2–%3, from %4, ended by %5</source>
        <translation>%1，第 %2–%3 行，始于 %4，结束原因：%5</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="241"/>
        <source>Cleaning (paper §IV.A): %1 of %2 rows kept; dropped for X_HDT %3, T_HDT %4, feed %5, missing cells %6, impossible values %7. Split: the first %8 rows train, the last %9 test.</source>
        <translation>清洗（论文 §IV.A）：%2 行中保留 %1 行；剔除原因：X_HDT %3，T_HDT %4，进料 %5，缺失值 %6，不可能的值 %7。划分：前 %8 行用于训练，后 %9 行用于测试。</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="254"/>
        <source>A row may fail more than one rule. The model uses %1 rows: those kept, less the rows where an input was bridged across a dropout.</source>
        <translation>一行可能不满足多条规则。模型使用 %1 行：即保留的行，再去掉输入在掉线处被桥接的行。</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="260"/>
        <source>A transmitter hung (the same reading for a minute or more) on %1 rows: left out, an input bridged like a dropout.</source>
        <translation>有变送器卡死（同一读数持续一分钟以上），涉及 %1 行：这些行不参与拟合，输入按断线同样桥接。</translation>
    </message>
    <message>
        <location filename="../widgets/data/DataPanel.cpp" line="265"/>
        <location filename="../widgets/data/DataPanel.cpp" line="279"/>
        <source>Noted while reading (%1):</source>
        <translation>读取时的提示（%1）：</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::DiagnosticsPanel</name>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="28"/>
        <source>Evaluate</source>
        <translation>评估</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="29"/>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="117"/>
        <source>Evaluate a trained model to see its residuals.</source>
        <translation>评估已训练的模型以查看其残差。</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="32"/>
        <source>ACF [-]</source>
        <translation>自相关 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="33"/>
        <source>lag [s]</source>
        <translation>滞后 [s]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="35"/>
        <source>PSD [(% wb)²/Hz]</source>
        <translation>PSD [(% 湿基)²/Hz]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="36"/>
        <source>frequency [Hz]</source>
        <translation>频率 [Hz]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="41"/>
        <source>Models shown (tick to overlay):</source>
        <translation>显示的模型（勾选以叠加）：</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="47"/>
        <source>error [% wb]</source>
        <translation>误差 [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="65"/>
        <source>Physics model&apos;s error against</source>
        <translation>机理模型误差相对于</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="69"/>
        <source>CCF [-]</source>
        <translation>互相关 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="70"/>
        <source>lag of the input [s] (run Discover)</source>
        <translation>输入的滞后 [s]（请运行发现）</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="100"/>
        <source>Learn the correction models (Residual model tab) to see the residuals&apos; autocorrelation</source>
        <translation>学习修正模型（残差模型页）后可看到残差的自相关</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="101"/>
        <source>… and their spectrum</source>
        <translation>……及其频谱</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="102"/>
        <source>Open data to see where in the operating range the physics model errs</source>
        <translation>打开数据，可看到物理模型在工况范围内何处出错</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="103"/>
        <source>Run Discover to see what the error moves with</source>
        <translation>运行发现，可看到误差随什么变化</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="135"/>
        <source>%1: Ljung-Box p %2, residual mean %3 % wb</source>
        <translation>%1：Ljung-Box p %2，残差均值 %3 % 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="143"/>
        <source>Ljung-Box p: the chance that errors this patterned come from pure noise; below 0.05 a pattern is left that a model could still learn.</source>
        <translation>Ljung-Box p：如此有规律的误差来自纯噪声的概率；低于 0.05 说明还剩有模型可以学习的规律。</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="176"/>
        <source>%1 (%2 % below 0.01 Hz)</source>
        <translation>%1（%2 % 低于 0.01 Hz）</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="182"/>
        <source>95 % band of white noise</source>
        <translation>白噪声 95 % 置信带</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="223"/>
        <source>every 10th kept row</source>
        <translation>保留行中每隔 10 行</translation>
    </message>
    <message>
        <location filename="../widgets/diagnostics/DiagnosticsPanel.cpp" line="272"/>
        <source>lag of the input [s]; the outlet-moisture error&apos;s correlation with each input</source>
        <translation>输入的滞后 [s]；出口水分误差与各输入的相关系数</translation>
    </message>
    <message>
        <source>lag of the input [s]</source>
        <translation>输入的滞后 [s]</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::DiscoverPanel</name>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="38"/>
        <source>Discover</source>
        <translation>发现</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="39"/>
        <source>What does the simulation get wrong, and why? (score tests, fits, held-out gain)</source>
        <translation>仿真哪里出错，为什么？（得分检验、拟合、留出数据上的改进）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="40"/>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="130"/>
        <source>Extend the model</source>
        <translation>扩展模型</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="43"/>
        <source>Make the extended model (named causes, refitted h_HDT and k_HDT, residual models retrained) the session&apos;s model</source>
        <translation>将扩展后的模型（已命名的原因、重新拟合的 h_HDT 与 k_HDT、重新训练的残差模型）设为当前模型</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="45"/>
        <source>Run discovery on the loaded data with the current model.</source>
        <translation>用当前模型在已加载的数据上运行发现。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="47"/>
        <location filename="../widgets/discovery/RankingWords.cpp" line="16"/>
        <source>Cause</source>
        <translation>原因</translation>
    </message>
    <message>
        <source>Score z</source>
        <translation>得分 z</translation>
    </message>
    <message>
        <source>p (Holm)</source>
        <translation>p（Holm）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="47"/>
        <location filename="../widgets/discovery/RankingWords.cpp" line="23"/>
        <source>Fitted</source>
        <translation>已拟合</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="47"/>
        <location filename="../widgets/discovery/RankingWords.cpp" line="24"/>
        <source>Loss</source>
        <translation>损失</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/RankingWords.cpp" line="19"/>
        <source>How far
it moved</source>
        <translation>变化
幅度</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/RankingWords.cpp" line="21"/>
        <source>How strong
the evidence is</source>
        <translation>证据
强度</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/RankingWords.cpp" line="22"/>
        <source>Chance it
is noise</source>
        <translation>属于噪声
的概率</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/RankingWords.cpp" line="39"/>
        <source>Score z: how strongly the model&apos;s error points at this cause, in standard deviations of chance; above about 3 is strong evidence.</source>
        <translation>得分 z：模型误差指向该原因的强度，以偶然波动的标准差计；约 3 以上为有力证据。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/RankingWords.cpp" line="43"/>
        <source>p (Holm): the chance of evidence this strong if the cause were absent, corrected for testing many causes at once (Holm&apos;s method); below 0.05 the cause is taken seriously.</source>
        <translation>p（Holm）：若该原因不存在，出现如此强证据的概率，已按同时检验多个原因校正（Holm 法）；低于 0.05 即应认真对待该原因。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/RankingWords.cpp" line="48"/>
        <source>Fitted: whether the cause&apos;s parameter was fitted to the data (only the leading causes are).</source>
        <translation>已拟合：该原因的参数是否已拟合到数据（只拟合排名靠前的原因）。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/RankingWords.cpp" line="53"/>
        <source>Loss: the fit&apos;s error with the cause in the model; lower is a better fit.</source>
        <translation>损失：模型加入该原因后拟合的误差；越低拟合越好。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/RankingWords.cpp" line="69"/>
        <source>From the cause&apos;s own score test (a timing cause is screened on its own signature), not the shared screen: that is why it can be small beside a small first number.</source>
        <translation>来自该原因自身的得分检验（时间类原因按其自身特征筛选），而非共同筛选：因此它可能在前一数值很小时也很小。</translation>
    </message>
    <message>
        <source>The held-out part: batches the fit did not see.</source>
        <translation>留出部分：拟合时未使用的批次。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="49"/>
        <source>Held-out</source>
        <translation>留出数据</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="47"/>
        <location filename="../widgets/discovery/RankingWords.cpp" line="17"/>
        <source>Outcome</source>
        <translation>结果</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/RankingWords.cpp" line="28"/>
        <source>Outcome: named, or why not (the whole reason in the cell&apos;s tooltip, and under the evidence).</source>
        <translation>结果：已指认，或未指认的理由（完整理由见单元格提示及证据下方）。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="49"/>
        <source>Before</source>
        <translation>之前</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="49"/>
        <source>After</source>
        <translation>之后</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="49"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Before: the starting model (as commissioned, or calibrated).</source>
        <translation>之前：起始模型（调试所得或标定后的模型）。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="59"/>
        <source>After: the extended model, every named cause fitted together (a finding&apos;s own sentence gives the gain when that cause was named).</source>
        <translation>之后：扩展后的模型，所有已识别原因一起拟合（各项发现的文字给出识别该原因时的改进）。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="63"/>
        <source>X_out residual [% wb]</source>
        <translation>X_out 残差 [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="64"/>
        <source>T_out residual [°C]</source>
        <translation>T_out 残差 [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="65"/>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="81"/>
        <source>time, batches one after another [h]</source>
        <translation>时间，批次首尾相接 [h]</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="68"/>
        <source>Compare with a reference period…</source>
        <translation>与参考期比较…</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="70"/>
        <source>Choose batches from a time when the line ran as it should (the weeks after a cleaning, commissioning runs): Discover then says whether, from when and why the loaded data differ</source>
        <translation>选择产线正常运行时期的批次（清洗后的几周、调试运行）：发现功能将说明已加载的数据是否、从何时起以及为何与之不同</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/ReferenceMenu.cpp" line="33"/>
        <source>The line&apos;s commissioning runs (%1 runs, %2)</source>
        <translation>产线的调试运行（%1 次运行，%2）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/ReferenceMenu.cpp" line="37"/>
        <source>The line&apos;s commissioning runs (%1)</source>
        <translation>产线的调试运行（%1）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/ReferenceMenu.cpp" line="41"/>
        <source>The runs the training line was commissioned on: what changed since then is named more surely than from the recording alone</source>
        <translation>培训产线调试时的运行：与仅凭记录相比，能更可靠地指出此后发生的变化</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/ReferenceMenu.cpp" line="50"/>
        <source>A folder of batch files…</source>
        <translation>批次文件所在的文件夹…</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/ReferenceMenu.cpp" line="54"/>
        <source>Reference period: a folder of batch files</source>
        <translation>参考期：批次文件所在的文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/ReferenceMenu.cpp" line="62"/>
        <source>One batch or historian file…</source>
        <translation>单个批次或历史库文件…</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/ReferenceMenu.cpp" line="66"/>
        <source>Reference period: a batch or historian file</source>
        <translation>参考期：批次或历史库文件</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/ReferenceMenu.cpp" line="69"/>
        <source>CSV files (*.csv *.txt)</source>
        <translation>CSV 文件 (*.csv *.txt)</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/ReferenceMenu.cpp" line="75"/>
        <source>No reference: judge the data alone</source>
        <translation>不用参考期：单独判断数据</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="79"/>
        <source>T² [-]</source>
        <translation>T² [-]</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="80"/>
        <source>SPE [-]</source>
        <translation>SPE [-]</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="84"/>
        <source>Choose a reference period and run Discover to see the monitor</source>
        <translation>选择参考期并运行“发现”以查看监控图</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="86"/>
        <source>Column</source>
        <translation>列</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="86"/>
        <source>Share of the change</source>
        <translation>在变化中的占比</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="86"/>
        <source>Detector</source>
        <translation>检测器</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="88"/>
        <source>How much each column contributes to the monitor&apos;s statistic after the onset (reconstruction-based contributions: the column that, put back to normal, removes most of it)</source>
        <translation>起始点之后各列对监控统计量的贡献（基于重构的贡献：将该列恢复正常后消除的部分最多者）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="95"/>
        <source>Model error</source>
        <translation>模型误差</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="96"/>
        <source>Monitor against the reference</source>
        <translation>相对参考期的监控</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="109"/>
        <source>Candidate causes, first round:</source>
        <translation>候选原因（第一轮）：</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="111"/>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="161"/>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="371"/>
        <source>Gain on the held-out part:</source>
        <translation>留出数据上的改进：</translation>
    </message>
    <message>
        <source>the model was extended by discovery</source>
        <translation>模型已由发现功能扩展</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="202"/>
        <source> The model is extended.</source>
        <translation> 模型已扩展。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="145"/>
        <source>Run Discover to see the physics model&apos;s error over the batches</source>
        <translation>运行发现，可看到物理模型在各批次上的误差</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="37"/>
        <source>No reference period: the data are judged alone.</source>
        <translation>无参考期：单独判断数据。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="38"/>
        <source>Reference period: %1</source>
        <translation>参考期：%1</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="54"/>
        <source>%1: &lt;b&gt;changed&lt;/b&gt; (p = %2)</source>
        <translation>%1：&lt;b&gt;已变化&lt;/b&gt;（p = %2）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="55"/>
        <source>%1: no change (p = %2)</source>
        <translation>%1：无变化（p = %2）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="57"/>
        <source>, first alarm in %1 at %2 min</source>
        <translation>，首次报警于 %1 第 %2 分钟</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="62"/>
        <source>, from %1 at %2 min (95 %: %3 to %4 min)</source>
        <translation>，自 %1 第 %2 分钟起（95 %：%3 至 %4 分钟）</translation>
    </message>
    <message>
        <source>DryTwin (the causes&apos; parameters): &lt;b&gt;changed&lt;/b&gt; (p = %1): %2 moved beyond its normal spread</source>
        <translation>DryTwin（各原因的参数）：&lt;b&gt;已变化&lt;/b&gt;（p = %1）：%2 超出其正常范围</translation>
    </message>
    <message>
        <source>DryTwin (the causes&apos; parameters): none moved beyond its normal spread (p = %1)</source>
        <translation>DryTwin（各原因的参数）：均未超出其正常范围（p = %1）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="110"/>
        <source>&lt;b&gt;The line has changed since the reference period.&lt;/b&gt;</source>
        <translation>&lt;b&gt;自参考期以来产线已发生变化。&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="117"/>
        <source>&lt;b&gt;No change against the reference period.&lt;/b&gt;</source>
        <translation>&lt;b&gt;与参考期相比无变化。&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="118"/>
        <source> Each detector&apos;s false-alarm rate: %1 % per data set.</source>
        <translation> 每个检测器的误报率：每个数据集 %1 %。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="119"/>
        <source>DryTwin (the model&apos;s error)</source>
        <translation>DryTwin（模型误差）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="121"/>
        <source>Dynamic PCA (the measured columns)</source>
        <translation>动态 PCA（测量列）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="146"/>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="162"/>
        <source>DryTwin</source>
        <translation>DryTwin</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="146"/>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="162"/>
        <source>dynamic PCA</source>
        <translation>动态 PCA</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="148"/>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="150"/>
        <source>99 % limit</source>
        <translation>99 % 限值</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="51"/>
        <source>the outlet-temperature error grows with the hot-air excess over ambient (bias by T_amb and T_hot)</source>
        <translation>出口温度误差随热风高出环境温度的幅度增大（按 T_amb 和 T_hot 分组的偏差）</translation>
    </message>
    <message>
        <source>the errors grow with feed rate and inlet moisture (bias by feed_kg_h and X_in_pct)</source>
        <translation type="vanished">误差随进料量和入口水分增大（按 feed_kg_h 和 X_in_pct 分组的偏差）</translation>
    </message>
    <message>
        <source>the error drifts within every batch and resets at each batch start</source>
        <translation>误差在每个批次内漂移，并在每个批次开始时复位</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="61"/>
        <source>the outlet-moisture error follows the rate of change of the simulated outlet moisture, and the tube-outlet error does not</source>
        <translation>出口水分误差跟随模拟出口水分的变化率，而管道出口误差不跟随</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="65"/>
        <source>a steady outlet-moisture bias that the tube-outlet moisture does not share</source>
        <translation>出口水分存在稳定偏差，而管道出口水分没有</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="68"/>
        <source>the outlet error correlates with tube-outlet changes at a shifted lag</source>
        <translation>出口误差与管道出口的变化在偏移的滞后处相关</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="70"/>
        <source>the tube-outlet and outlet moisture are wetter than simulated, most where the tube dries furthest</source>
        <translation>管道出口和出口水分比模拟值更湿，在管道干燥程度最深处最明显</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="74"/>
        <source>the outlet-moisture error grows with ambient humidity while the tube-outlet error does not</source>
        <translation>出口水分误差随环境湿度增大，而管道出口误差不随之变化</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="78"/>
        <source>a steady bias of the tube-outlet and outlet moisture alike, larger where the tube dries less</source>
        <translation>干燥管出口与出口水分有相同的稳定偏差，干燥管干燥越少处越大</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="81"/>
        <source>after each hot-air setpoint step the outlet temperature and moisture move before the simulation, which follows the slow reading</source>
        <translation>每次热风设定值阶跃后，出口温度和水分先于仿真变化，仿真跟随的是迟缓的读数</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="84"/>
        <source>the inlet-moisture reading scatters from second to second while the outlet does not follow it, and the simulated outlet does</source>
        <translation>入口水分读数逐秒跳动，出口并不跟随，而仿真的出口却跟随</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="94"/>
        <source>a step of the hot-air setpoint logged at 1 s: a transport-time error delays the outlet temperature&apos;s response as much as the moisture&apos;s, a meter lag delays the moisture reading alone; or grab samples timed against the meter</source>
        <translation>以 1 s 记录一次热风设定值阶跃：输送时间误差使出口温度与水分的响应同样延迟，水分仪滞后只延迟水分读数；或对照水分仪定时取样</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="101"/>
        <source>oven-dry laboratory samples at the outlet against the meter and at the inlet against the gauge; or a tube-outlet moisture channel (X_hdt), which an inlet-gauge offset moves and an outlet-meter offset does not</source>
        <translation>在出口对照水分仪、在入口对照入口水分计做烘箱法实验室取样；或增加干燥管出口水分通道（X_hdt）：入口水分计偏差会使其变化，出口水分仪偏差不会</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="108"/>
        <source>a gas-temperature reading at the tube&apos;s outlet end at two feed rates: wall loss does not change with the feed, gas-phase cooling grows with it</source>
        <translation>在两种喂料量下测量干燥管出口端的气体温度：管壁散热不随喂料量变化，气相冷却随之增大</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="135"/>
        <source>it lowers one output&apos;s error by raising another&apos;s (compensation)</source>
        <translation>它以增大另一输出的误差为代价降低一个输出的误差（补偿）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="138"/>
        <source>its size is not consistent across batches or operating regions</source>
        <translation>其大小在各批次或各工况区间之间不一致</translation>
    </message>
    <message>
        <source>an offset reads the same all batch long; this error grows or shrinks within the batch (fouling, a drifting reading)</source>
        <translation type="vanished">偏差在整个批次中读数不变；此误差在批次内增大或减小（结垢、读数漂移）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="146"/>
        <source>its value lies within the reference period&apos;s normal range: not a change</source>
        <translation>其值在参考期的正常范围内：不是变化</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="149"/>
        <source>named after another cause, it must lower the error of every output it acts on, and on one it does not: what is left there is not this cause&apos;s</source>
        <translation>它是在另一个原因之后提出的，必须降低它所作用的每个输出的误差，而在其中一个输出上没有做到：那里剩下的误差不是这个原因造成的</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="154"/>
        <source>it is below what the instruments can tell (practical floor)</source>
        <translation>它低于仪表能分辨的程度（实用下限）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="157"/>
        <source>it does not predict the held-out part clearly better (too small a share of the error, or not significant)</source>
        <translation>它对留出部分的预测没有明显改善（消除的误差比例太小，或不显著）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="161"/>
        <source>the outlet channels&apos; timing points to its look-alike (the moisture answers later than the temperature: a meter, not the transport)</source>
        <translation>出口两个通道的时序指向它的相似原因（水分比温度响应更晚：是水分仪，而非输送）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="166"/>
        <source>the outlet temperature lags the model as much: the line is slower than the model, not the meter</source>
        <translation>出口温度同样滞后于模型：是产线比模型慢，而不是水分仪</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="169"/>
        <source>no clear held-out gain</source>
        <translation>在留出数据上没有明确的改进</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="236"/>
        <source>X_hdt_pct is not measured: without the tube-outlet moisture, meter and conveyor causes cannot be told from tube causes; only the outlet channels are used.</source>
        <translation>未测量 X_hdt_pct：没有管出口含水率，无法区分仪表和输送原因与干燥管原因；只使用出口通道。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="240"/>
        <source>T_hdt_C is not measured: the tube-outlet temperature is not used.</source>
        <translation>未测量 T_hdt_C：不使用管出口温度。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="243"/>
        <source>air_speed_m_s is constant (not measured?): the air cooling along the tube is fitted with that one value.</source>
        <translation>air_speed_m_s 为常数（未测量？）：沿管风冷却按这一个值拟合。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="247"/>
        <source>The line&apos;s outlet mixing (belt and winnower): a first-order lag of %1 s fitted with h_HDT and k_HDT (0: plug flow).</source>
        <translation>产线出口混合（输送带和风选机）：与 h_HDT、k_HDT 一起拟合的一阶滞后 %1 s（0：活塞流）。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="252"/>
        <source>The inlet gauge&apos;s normal scatter: %1 % of X_in&apos;s fast variation (%2 % wb) is taken as gauge scatter, not moisture, in the starting model.</source>
        <translation>入口水分仪的正常波动：在初始模型中，X_in 快速变化（%2 % 湿基）的 %1 % 被视为仪表波动而非真实水分。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="175"/>
        <source>a periodic error of %1 s period (power %2 times its background)</source>
        <translation>周期为 %1 s 的周期性误差（功率为背景的 %2 倍）</translation>
    </message>
    <message>
        <source>the error follows %1 %2 s later (|ccf| %3)</source>
        <translation type="vanished">误差在 %1 之后 %2 s 跟随变化（|ccf| %3）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="190"/>
        <source>batches %1 are shifted by %2 against the others</source>
        <translation>批次 %1 相对其他批次偏移 %2</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="195"/>
        <source>the error drifts by %1 per hour within the batches</source>
        <translation>误差在批次内每小时漂移 %1</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="207"/>
        <source>no candidate passes the screening test</source>
        <translation>没有候选原因通过筛选检验</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="214"/>
        <source>no fitted candidate lowers the training loss</source>
        <translation>没有拟合的候选原因降低训练损失</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="314"/>
        <source>%1 is typically %2 %3, outside what the other reference batches saw (%4 to %5 %3)</source>
        <translation>%1 通常为 %2 %3，超出其他参考批次所见范围（%4 至 %5 %3）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="316"/>
        <source>%1 is typically %2 %3, outside what the reference saw (%4 to %5 %3)</source>
        <translation>%1通常为 %2 %3，超出参考期见过的范围（%4 至 %5 %3）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="319"/>
        <source>; </source>
        <translation>；</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="327"/>
        <source>Reference batch %1: %2: the line&apos;s structure there is the map&apos;s extrapolation, so the batch is left out of the causes&apos; normal spread.</source>
        <translation>参考批次 %1：%2：该批次上产线结构的修正是映射的外推，因此该批次不计入各原因的正常离散度。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="341"/>
        <source>%1: %2: the reference has no normal level for these conditions, so the detectors judge only changes within this batch, not its level.</source>
        <translation>%1：%2：参考期没有这种工况下的正常水平，因此两个检测器只判断该批次内部的变化，不判断其水平。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="343"/>
        <source>%1: %2: the model&apos;s error there is judged beyond the reference&apos;s conditions, and an alarm there may be that condition rather than a change of the line.</source>
        <translation>%1：%2：该处模型误差是在参考期条件之外判断的，报警可能来自这一工况，而不是生产线的变化。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="415"/>
        <source>Fitted part by part (%1 parts) it lies between %2 and %3 %4: %5.</source>
        <translation>逐段拟合（%1 段）时其值在 %2 与 %3 %4 之间：%5。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="420"/>
        <source>consistent</source>
        <translation>一致</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="420"/>
        <source>not consistent</source>
        <translation>不一致</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="426"/>
        <source>Fitted on the cooler half of the data it removes %1 % of the warmer half&apos;s error.</source>
        <translation>用较冷的一半数据拟合，它消除较热一半数据误差的 %1 %。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="430"/>
        <source>It starts %1 min into the batch (95 % interval %2–%3 min).</source>
        <translation>它在批次开始后 %1 min 出现（95 % 区间 %2–%3 min）。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="455"/>
        <source>Not %1: the moisture answers %2 s later than the model and the outlet temperature %3 s (each fitted alone, p = %4); a transport time delays both alike.</source>
        <translation>不是 %1：水分比模型晚 %2 s 响应，出口温度晚 %3 s（各自单独拟合，p = %4）；输送时间会使二者同样延迟。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="461"/>
        <source>%1 fits too: the moisture answers %2 s later than the model and the outlet temperature %3 s (each fitted alone, p = %4); the channels&apos; timing cannot tell them apart (the temperature has dynamics of its own, or the difference is within the noise).</source>
        <translation>%1 也同样吻合：水分比模型晚 %2 s 响应，出口温度晚 %3 s（各自单独拟合，p = %4）；两个通道的时序无法区分二者（温度有其自身的动态，或差异在噪声范围内）。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="444"/>
        <source>%1 was named on top of it (a further %2 % of the held-out error): alone it predicts worse (%3 times the held-out error), but the change needs both forms, so the data cannot say which of them it is.</source>
        <translation>在它之上又判定了 %1（再减少留出误差的 %2 %）：单独使用时预测更差（留出误差的 %3 倍），但这一变化需要两种形式共同解释，因此数据无法判断是其中哪一个。</translation>
    </message>
    <message>
        <source>DryTwin (the causes&apos; one-step estimates): &lt;b&gt;changed&lt;/b&gt; (p = %1): %2 moved beyond its normal spread</source>
        <translation>DryTwin（各原因的一步估计）：&lt;b&gt;已变化&lt;/b&gt;（p = %1）：%2 超出其正常范围</translation>
    </message>
    <message>
        <source>DryTwin (the causes&apos; one-step estimates): none moved beyond its normal spread (p = %1)</source>
        <translation>DryTwin（各原因的一步估计）：均未超出其正常范围（p = %1）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="112"/>
        <source>&lt;b&gt;A cause has changed since the reference period: %1.&lt;/b&gt; The detectors, judging the data set as a whole, stayed below their limits; fitting the causes found it beyond its normal spread with a gain on held-out data (below). Check it on the plots.</source>
        <translation>&lt;b&gt;自参考期以来有一个原因发生了变化：%1。&lt;/b&gt;检测器对整个数据集的判断未超出其限值；拟合各原因发现它超出正常范围，且在留出数据上有改进（见下）。请在图上核对。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="57"/>
        <source>the error drifts over each batch, or over the recording from the fouling&apos;s onset, and starts afresh with each new batch</source>
        <translation>误差在每个批次内（或在记录中自结垢开始起）逐渐漂移，每个新批次重新开始</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="129"/>
        <source>not named</source>
        <translation>未指认</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="261"/>
        <source>%1 was named first, then withdrawn: refitted together with the causes named after it, it is no change of the line (it had taken up what they explain). In detail: %2.</source>
        <translation>%1 先被识别，随后撤回：与之后识别的原因一起重新拟合后，它并非产线的变化（它曾吸收了那些原因所解释的部分）。详情：%2。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="271"/>
        <source>The causes are judged on the batches from %1 on, where the change began; %2 before it ran as the reference did.</source>
        <translation>原因按从 %1 起的批次判断，变化从那里开始；此前的 %2 与参考期运行一致。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="280"/>
        <source>The change goes on from the start of %1 (the monitor reads them changed before the onset time too): the causes act there from the batch&apos;s start.</source>
        <translation>变化从 %1 的开始起持续（监测器在起始时间之前也判定这些批次已变化）：原因在这些批次中从批次开始起作用。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="285"/>
        <source>The reference holds %1 batch(es): a period&apos;s normal spread comes from thirds of them, which share their day and weather; a change named here may be a difference of conditions the reference never showed. A reference of several batches over the conditions the line runs in (weeks, seasons) judges better.</source>
        <translation>参考期仅含 %1 个批次：一个时段的正常离散取自其三等分，它们同属一天、同样天气；此处识别出的变化可能只是参考期从未出现过的工况差异。覆盖产线运行工况（数周、不同季节）的多批次参考期判断得更好。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="297"/>
        <source>The reference period itself drifts: the model&apos;s %1 error changes by %2 %3 within a mean batch. A reference should be a period when the line ran well; against this one a change since may read as none.</source>
        <translation>参考期本身在漂移：模型的 %1 误差在一个平均批次内变化 %2 %3。参考期应是产线运行良好的时段；以此为参考，之后的变化可能显示为无变化。</translation>
    </message>
    <message>
        <source>Reference batch %1: %2 is typically %3 %4, outside what the other reference batches saw (%5 to %6 %4): the line&apos;s structure there is the map&apos;s extrapolation, so the batch is left out of the causes&apos; normal spread.</source>
        <translation type="vanished">参考批次 %1：%2 通常为 %3 %4，超出其他参考批次所见范围（%5 至 %6 %4）：该批次上产线结构的修正是映射的外推，因此该批次不计入各原因的正常离散度。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="354"/>
        <source>Only the causes asked were tried: %1. That the others are not named says nothing about them.</source>
        <translation>只试了所问的原因：%1。其他原因未被指认，并不说明它们不存在。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="364"/>
        <source>Commissioned on the reference period (%1 batch(es), %2 rows): h_HDT %3 W/(m²·K) and k_HDT %4 m/s, held fixed on the data judged.</source>
        <translation>已在参考期上调试（%1 个批次，%2 行）：h_HDT %3 W/(m²·K)，k_HDT %4 m/s，在所判断的数据上保持不变。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="372"/>
        <source>The line&apos;s own structure (what the model always gets wrong: a ridge regression on the inputs and the model&apos;s outputs, penalty %1) was learnt on the reference and taken off the measurements; the residuals shown are what is left.</source>
        <translation>产线自身的结构（模型总是出错的部分：基于输入和模型输出的岭回归，惩罚系数 %1）已在参考期上学习，并从测量值中扣除；所示残差为剩余部分。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="384"/>
        <source>%1 is measured in the data but not in every batch of the reference period: the periods are compared on the outputs both measure, without it.</source>
        <translation>%1 在数据中有测量，但参考期并非每个批次都有：两个时期只在双方都测量的输出上比较，不含它。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="387"/>
        <source>%1 is measured in the reference period but not in every batch of the data: the periods are compared on the outputs both measure, without it.</source>
        <translation>%1 在参考期中有测量，但数据并非每个批次都有：两个时期只在双方都测量的输出上比较，不含它。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="394"/>
        <source>The reference period&apos;s files: %1</source>
        <translation>参考期的文件：%1</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="422"/>
        <source>A part whose estimate left the parameter&apos;s range is held at its bound.</source>
        <translation>某一部分的估计值超出了参数范围，已按其边界处理。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="439"/>
        <source>It goes on from the start of %1.</source>
        <translation>它从 %1 的开始起持续存在。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="474"/>
        <source>%1 fits too: overall it leaves %2 times the held-out error (p = %3), but it predicts %4 better; which output a cause favours is the model&apos;s structure, so the data cannot tell them apart.</source>
        <translation>%1 同样拟合：总体上它留下 %2 倍的留出误差（p = %3），但它对%4的预测更好；原因偏向哪个输出取决于模型自身的结构，因此数据无法区分二者。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="480"/>
        <source>the outlet moisture</source>
        <translation>出口含水率</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="481"/>
        <source>the outlet temperature</source>
        <translation>出口温度</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="482"/>
        <source>the tube-outlet moisture</source>
        <translation>管出口含水率</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="483"/>
        <source>the tube-outlet temperature</source>
        <translation>管出口温度</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="487"/>
        <source>Not %1: fitted in its place it leaves %2 times the held-out error (p = %3).</source>
        <translation>不是 %1：以它代替拟合后留出误差为 %2 倍（p = %3）。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="488"/>
        <source>%1 fits these data about as well (held-out error %2 times, p = %3): the data cannot tell them apart.</source>
        <translation>%1 对这些数据拟合得差不多好（留出误差 %2 倍，p = %3）：数据无法区分二者。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="495"/>
        <source>To tell them apart: %1.</source>
        <translation>区分方法：%1。</translation>
    </message>
    <message>
        <source>it removes %1 % of the held-out squared error and %2 % of the outlet moisture&apos;s, the only measured output it acts on</source>
        <translation type="vanished">它消除了留出数据平方误差的 %1 %，以及出口水分误差的 %2 %（出口水分是它唯一作用的测量输出）</translation>
    </message>
    <message>
        <source>it removes %1 % of the held-out squared error and %2 % of the outlet moisture&apos;s and temperature&apos;s, the only measured outputs it acts on</source>
        <translation type="vanished">它消除了留出数据平方误差的 %1 %，以及出口水分和温度误差的 %2 %（二者是它唯一作用的测量输出）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="517"/>
        <source>it removes %1 % of the held-out squared error and %2 % of its fast part (the error about its moving average, where slow drift does not hide it)</source>
        <translation>它消除了留出数据平方误差的 %1 %，以及其快速部分（误差相对其滑动平均的部分，慢漂移不会掩盖它）的 %2 %</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="521"/>
        <source>it removes %1 % of the held-out squared error</source>
        <translation>它消除了留出数据平方误差的 %1 %</translation>
    </message>
    <message>
        <source>%1 error before: bias %2 %3, within-batch trend %4 %3/h. With %5 (%6 = %7 %8, 95 % CI [%9, %10]) and h_HDT, k_HDT refitted, the held-out MAE of X_out falls from %11 to %12 % wb and of T_out from %13 to %14 °C (Diebold-Mariano p = %15); %16. Check on the plots: %17.</source>
        <translation>扩展前的%1误差：偏差 %2 %3，批次内趋势 %4 %3/h。加入 %5（%6 = %7 %8，95 % 置信区间 [%9, %10]）并重新拟合 h_HDT、k_HDT 后，留出数据上 X_out 的 MAE 从 %11 降至 %12 % 湿基，T_out 从 %13 降至 %14 °C（Diebold-Mariano p = %15）；%16。在图上检查：%17。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="538"/>
        <source>Outlet-moisture</source>
        <translation>出口水分</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="538"/>
        <source>Outlet-temperature</source>
        <translation>出口温度</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="567"/>
        <source> %1 moved against this cause&apos;s effect (%2 times what its model form says), by less than that output&apos;s noise can tell from none: it counts neither for the cause nor against it.</source>
        <translation> %1 的变化与该原因的作用方向相反（为其模型形式所预测的 %2 倍），但小于该输出的噪声所能分辨的程度：既不支持也不否定该原因。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="156"/>
        <source>Run discovery on %1 with the current model.</source>
        <translation>用当前模型在 %1 上运行发现。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="157"/>
        <source>Open a data set, then run discovery on it.</source>
        <translation>请先打开数据集，再在其上运行发现。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="175"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <source>one of %1 (look-alikes)</source>
        <translation>%1 之一（相似原因）</translation>
    </message>
    <message>
        <source>Verdict: %1. No mechanism is named.</source>
        <translation>结论：%1。未命名任何机理。</translation>
    </message>
    <message>
        <source>Verdict: %1. Named: %2.</source>
        <translation>结论：%1。已命名：%2。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="246"/>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="246"/>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <source>%1 at %2 s (ccf %3%4)</source>
        <translation type="vanished">%1，滞后 %2 s（互相关 %3%4）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="297"/>
        <source>, significant</source>
        <translation>，显著</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="300"/>
        <source>&lt;p&gt;&lt;b&gt;%1&lt;/b&gt; error moves with: %2&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;%1&lt;/b&gt; 误差随以下变量变化：%2&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Round %1&lt;/b&gt;: %2 (held-out p = %3; removes %4 % of the error, %5 % of its fast part): %6&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;第 %1 轮&lt;/b&gt;：%2（保留集 p = %3；消除误差的 %4 %，其快速部分的 %5 %）：%6&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="215"/>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="204"/>
        <source>named</source>
        <translation>已确认</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="51"/>
        <source>The held-out part: the last 30 % of the rows, batches in time order (the Residual model tab&apos;s split); every fit saw only the rows before it.</source>
        <translation>留出部分：按时间顺序排列批次后最后 30 % 的行（与“残差模型”标签页的划分相同）；每次拟合只看到它之前的行。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="55"/>
        <source>Before: discovery&apos;s starting model, with h_HDT, k_HDT and the inlet gauge&apos;s scatter fitted to these data&apos;s training rows (or as commissioned on the reference period). It can differ from the Calibrate tab&apos;s model, and so from the physics model&apos;s error on the Residual model tab.</source>
        <translation>之前：发现功能的起始模型，其 h_HDT、k_HDT 和入口测量仪散布按这些数据的训练行拟合（或按参考期调试所得）。它可能与“标定”标签页的模型不同，因此也可能与“残差模型”标签页上物理模型的误差不同。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="79"/>
        <source>DryTwin (the causes&apos; estimates): none moved beyond its normal spread (p %1)</source>
        <translation>DryTwin（各原因的估计）：均未超出其正常范围（p %1）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="81"/>
        <source>DryTwin (the causes&apos; one-step estimates): &lt;b&gt;changed&lt;/b&gt; (p %1): %2 moved beyond its normal spread</source>
        <translation>DryTwin（各原因的一步估计）：&lt;b&gt;已变化&lt;/b&gt;（p %1）：%2 超出其正常范围</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="85"/>
        <source>DryTwin (the inlet gauge&apos;s own scatter): &lt;b&gt;changed&lt;/b&gt; (p %1): %2 rose beyond the reference&apos;s</source>
        <translation>DryTwin（进口水分仪自身的散布）：&lt;b&gt;已变化&lt;/b&gt;（p %1）：%2 高于参考期</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="88"/>
        <source>DryTwin (a named cause&apos;s fitted value): &lt;b&gt;changed&lt;/b&gt; (p %1): %2 moved beyond its normal spread</source>
        <translation>DryTwin（已命名原因的拟合值）：&lt;b&gt;已变化&lt;/b&gt;（p %1）：%2 超出其正常范围</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="508"/>
        <source>it removes %1 % of the held-out squared error, and of the outlet moisture&apos;s, the only measured output it acts on, %2 % (%3 % of its fast part)</source>
        <translation>它消除了留出数据平方误差的 %1 %；在出口水分（它唯一作用的测量输出）上消除 %2 %（快速部分的 %3 %）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="511"/>
        <source>it removes %1 % of the held-out squared error, and of the outlet moisture&apos;s and temperature&apos;s, the only measured outputs it acts on, %2 % (%3 % of its fast part)</source>
        <translation>它消除了留出数据平方误差的 %1 %；在出口水分和温度（它唯一作用的测量输出）上消除 %2 %（快速部分的 %3 %）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="522"/>
        <source>h_HDT, k_HDT as commissioned on the reference period</source>
        <translation>h_HDT、k_HDT 取参考期调试所得值</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="523"/>
        <source>h_HDT, k_HDT refitted</source>
        <translation>并重新拟合 h_HDT、k_HDT 后</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="527"/>
        <source> On the reference period it was %1 %2 (a period&apos;s normal range %3 to %4): it changed.</source>
        <translation> 在参考期它为 %1 %2（一个时段的正常范围 %3 至 %4）：它发生了变化。</translation>
    </message>
    <message>
        <source>%1 error before: bias %2 %3, within-batch trend %4 %3/h. With %5 (%6 = %7 %8, 95 % CI [%9, %10]) and %18, the held-out MAE of X_out falls from %11 to %12 % wb and of T_out from %13 to %14 °C (Diebold-Mariano p = %15); %16. Check on the plots: %17.</source>
        <translation>扩展前的%1误差：偏差 %2 %3，批次内趋势 %4 %3/h。加入 %5（%6 = %7 %8，95 % 置信区间 [%9, %10]），%18，留出数据上 X_out 的 MAE 从 %11 降至 %12 % 湿基，T_out 从 %13 降至 %14 °C（Diebold-Mariano p = %15）；%16。在图上检查：%17。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="178"/>
        <source>%1, one of: %2</source>
        <translation>%1，可能是：%2</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="199"/>
        <source>%1. On %2.</source>
        <translation>%1。数据：%2。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="200"/>
        <location filename="../widgets/discovery/DiscoverPanelDetection.cpp" line="107"/>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="356"/>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <source>%1 error before: bias %2 %3, within-batch trend %4 %3/h. With %5 (%6 = %7%8, 95 % CI [%9, %10]) and %18, the held-out MAE of X_out falls from %11 to %12 % wb and of T_out from %13 to %14 °C (Diebold-Mariano p = %15: the chance that a gain this large is luck); %16. Check on the plots: %17.</source>
        <translation type="vanished">扩展前的%1误差：偏差 %2 %3，批次内趋势 %4 %3/h。加入 %5（%6 = %7%8，95 % 置信区间 [%9, %10]），%18，留出数据上 X_out 的 MAE 从 %11 降至 %12 % 湿基，T_out 从 %13 降至 %14 °C（Diebold-Mariano p = %15：如此大的改进纯属偶然的概率）；%16。在图上检查：%17。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="203"/>
        <source>Discovery&apos;s verdict key: %1</source>
        <translation>发现结论代码：%1</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="216"/>
        <source>Named on its fit: it lowers the held-out error (p = %1) and passes the checks that it is this cause; the screen&apos;s p only ranks the candidates for fitting.</source>
        <translation>按其拟合指认：它降低了留出部分的误差（p = %1），并通过了确认是此原因的各项检查；筛选的 p 只用于为拟合排列候选。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="231"/>
        <source>fitted, not the best</source>
        <translation>已拟合，非最佳</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="232"/>
        <source>Fitted in a round in which another cause explained more of the error; the causes named after it were fitted on the model extended by it.</source>
        <translation>在某一轮中已拟合，但另一原因解释了更多误差；其后指认的原因是在由它扩展的模型上拟合的。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="243"/>
        <source>not fitted (weaker)</source>
        <translation>未拟合（证据较弱）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="320"/>
        <source>&lt;p&gt;&amp;nbsp;&amp;nbsp;Not named: %1, because %2.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&amp;nbsp;&amp;nbsp;未认定：%1，因为%2。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="336"/>
        <source>&lt;p&gt;&lt;b&gt;Not named&lt;/b&gt;; what the data allow (95 %): %1&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;未确认&lt;/b&gt;；数据允许的范围（95 %）：%1&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="345"/>
        <source>&lt;p&gt;&lt;b&gt;Unexplained&lt;/b&gt; (%1): the error follows the simulated rate of change (a lag of %2 s would explain %3 % of it): the line&apos;s dynamics differ from the model&apos;s.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;未解释&lt;/b&gt;（%1）：误差跟随仿真值的变化率（%2 s 的滞后可解释其 %3 %）：产线的动态与模型不同。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="352"/>
        <source>&lt;p&gt;&lt;b&gt;Unexplained&lt;/b&gt; (%1): %2&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;未解释&lt;/b&gt;（%1）：%2&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="357"/>
        <source>&lt;p&gt;&lt;b&gt;The correction model learnt on the extended physics model predicts worse on the held-out part than the one on the starting model: Extend keeps the starting model and its correction model; the findings stand.&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;在扩展物理模型上学得的修正模型在留出数据上的预测比在初始模型上的差：“扩展”保留初始模型及其修正模型；结论仍然成立。&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="365"/>
        <source>&lt;p&gt;No structure that a mechanism explains.&lt;/p&gt;</source>
        <translation>&lt;p&gt;没有可由机理解释的结构。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="385"/>
        <source>MAE X_out (physics)</source>
        <translation>MAE X_out（机理）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="386"/>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="412"/>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="502"/>
        <source>% wb</source>
        <translation>% 湿基</translation>
    </message>
    <message>
        <source>%1 error before: bias %2 %3, within-batch trend %4 %3/h. With %5 (%6 = %7%8, 95 % CI [%9, %10]) and %18, the held-out MAE of X_out goes from %11 to %12 % wb and of T_out from %13 to %14 °C (Diebold-Mariano p = %15: the chance that a gain this large is luck); %16. Check on the plots: %17.</source>
        <translation>扩展前的%1误差：偏差 %2 %3，批次内趋势 %4 %3/h。加入 %5（%6 = %7%8，95 % 置信区间 [%9, %10]），%18，留出数据上 X_out 的 MAE 从 %11 变为 %12 % 湿基，T_out 从 %13 变为 %14 °C（Diebold-Mariano p = %15：如此大的改进纯属偶然的概率）；%16。在图上检查：%17。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="387"/>
        <source>MAE T_out (physics)</source>
        <translation>MAE T_out（机理）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="388"/>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="416"/>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="502"/>
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <source>DryTwin (the causes&apos; estimates): none moved beyond its normal spread (p = %1)</source>
        <translation>DryTwin（各原因的估计）：均未超出其正常范围（p = %1）</translation>
    </message>
    <message>
        <source>DryTwin (the named causes&apos; fitted values, the inlet gauge&apos;s scatter): &lt;b&gt;changed&lt;/b&gt; (p = %1): %2 moved beyond its normal spread</source>
        <translation>DryTwin（已命名原因的拟合值、进口水分仪的散布）：&lt;b&gt;已变化&lt;/b&gt;（p = %1）：%2 超出其正常范围</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="54"/>
        <source>the errors grow with feed rate and inlet moisture (bias by feed rate and by inlet moisture)</source>
        <translation>误差随进料量和入口水分增大（按进料量和按入口水分分组的偏差）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="141"/>
        <source>it does not change within a batch (an offset, the tube&apos;s wall or gas phase), but this error grows or shrinks within the batch (fouling, a drifting reading)</source>
        <translation>它在批次内不变（偏差、管壁或气相），但此误差在批次内增大或减小（结垢、读数漂移）</translation>
    </message>
    <message>
        <source>%1: %2 is typically %3 %4, outside what the reference saw (%5 to %6 %4): the reference has no normal level for these conditions, so the detectors judge only changes within this batch, not its level.</source>
        <translation type="vanished">%1：%2通常为 %3 %4，超出参考期见过的范围（%5 至 %6 %4）：参考期没有这种工况下的正常水平，因此两个检测器只判断该批次内部的变化，不判断其水平。</translation>
    </message>
    <message>
        <source>%1: %2 is typically %3 %4, outside what the reference saw (%5 to %6 %4): the model&apos;s error there is judged beyond the reference&apos;s conditions, and an alarm there may be that condition rather than a change of the line.</source>
        <translation type="vanished">%1：%2通常为 %3 %4，超出参考期见过的范围（%5 至 %6 %4）：该处模型误差是在参考期条件之外判断的，报警可能来自这一工况，而不是生产线的变化。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="180"/>
        <source>the error follows %1 %2 s later (correlation %3)</source>
        <translation>误差在 %1 之后 %2 s 跟随变化（相关系数 %3）</translation>
    </message>
    <message>
        <source>%1 error before: bias %2 %3, within-batch trend %4 %3/h. With %5 (%6 = %7 %8, 95 % CI [%9, %10]) and %18, the held-out MAE of X_out falls from %11 to %12 % wb and of T_out from %13 to %14 °C (Diebold-Mariano p = %15: the chance that a gain this large is luck); %16. Check on the plots: %17.</source>
        <translation>扩展前的%1误差：偏差 %2 %3，批次内趋势 %4 %3/h。加入 %5（%6 = %7 %8，95 % 置信区间 [%9, %10]），%18，留出数据上 X_out 的 MAE 从 %11 降至 %12 % 湿基，T_out 从 %13 降至 %14 °C（Diebold-Mariano p = %15：如此大的改进纯属偶然的概率）；%16。在图上检查：%17。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="570"/>
        <source> %1 moved %2 times as much as this cause&apos;s model form says: the direction agrees, the size is the model&apos;s to answer.</source>
        <translation> %1 的变化是该原因模型形式所预测的 %2 倍：方向一致，幅度是模型需要解释的问题。</translation>
    </message>
    <message>
        <source>Change z</source>
        <translation>变化 z</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/RankingWords.cpp" line="34"/>
        <source>Change z: how far the cause&apos;s one-step estimate here lies from its normal value on the reference period, in units of both estimates&apos; errors and the spread between the reference&apos;s periods; above 2 it moved.</source>
        <translation>变化 z：该原因在此处的一步估计与其在参考期的正常值相差多远，以两次估计的误差及参考期各时段间的离散为单位；大于 2 即为发生了变化。</translation>
    </message>
    <message>
        <source>not named: %1</source>
        <translation>未指认：%1</translation>
    </message>
    <message>
        <source>not fitted: weaker evidence than those fitted</source>
        <translation>未拟合：证据弱于已拟合的候选</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanelTexts.cpp" line="533"/>
        <source>%1 error before: bias %2 %3, within-batch trend %4 %3/h. With %5 (%6 = %7%8, 95 % CI [%9, %10]) and %18, the held-out MAE of X_out goes from %11 to %12 % wb and of T_out from %13 to %14 °C (the chance that a gain this large is luck: %15); %16. Check on the plots: %17.</source>
        <translation>扩展前的%1误差：偏差 %2 %3，批次内趋势 %4 %3/h。加入 %5（%6 = %7%8，95 % 置信区间 [%9, %10]），%18，留出数据上 X_out 的 MAE 从 %11 变为 %12 % 湿基，T_out 从 %13 变为 %14 °C（如此大的改进纯属偶然的概率：%15）；%16。在图上检查：%17。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="257"/>
        <source>* A timing cause: p is its own score test (how strongly the error points at it), smaller than its change test&apos;s; a lag&apos;s one-step estimate understates how far it moved, so the fit decides.</source>
        <translation>* 时间类原因：p 来自其自身的得分检验（误差指向它的强度），小于其变化检验的 p；滞后的一步估计会低估其变化幅度，因此由拟合来决定。</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="272"/>
        <source>%1 = %2%3, 95 % CI [%4, %5]</source>
        <translation>%1 = %2%3，95 % 置信区间 [%4, %5]</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="279"/>
        <source> in the final model, fitted with every other named cause (%1%2 when it was named, as below)</source>
        <translation>（最终模型中与其他所有已识别原因一起拟合；识别时为 %1%2，如下文）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="293"/>
        <source>%1, %2 s earlier (correlation %3%4)</source>
        <translation>%1，提前 %2 s（相关系数 %3%4）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="310"/>
        <source>&lt;p&gt;&lt;b&gt;Round %1&lt;/b&gt;: %2 (chance the held-out gain is luck %3, Diebold-Mariano test; removes %4 % of the error, %5 % of its fast part): %6&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;第 %1 轮&lt;/b&gt;：%2（留出部分的改进纯属偶然的概率 %3，Diebold-Mariano 检验；消除误差的 %4 %，快速部分的 %5 %）：%6&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="340"/>
        <source>&lt;p&gt;The patterns left in the error below are within what the reference period shows: the data did not change against it.&lt;/p&gt;</source>
        <translation>&lt;p&gt;下列误差中残留的模式在参考期所示的范围之内：数据相对参考期没有变化。&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="370"/>
        <source>Held-out accuracy: nothing was named, so nothing was extended (before = after):</source>
        <translation>留出部分的精度：未指认原因，因此未扩展模型（前 = 后）：</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="375"/>
        <source>Gain on the held-out part, with every named cause (each finding&apos;s own gain is in its evidence):</source>
        <translation>留出部分的改进（含所有已指认的原因；每项发现各自的改进见其证据）：</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="389"/>
        <source>R² X_out</source>
        <translation>R² X_out</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="398"/>
        <source>low-frequency share</source>
        <translation>低频占比</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="411"/>
        <source>MAE X_out (PGRL-CC)</source>
        <translation>MAE X_out（PGRL-CC）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="411"/>
        <source>MAE X_out (last value held)</source>
        <translation>MAE X_out（保持上一测量值）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="412"/>
        <source>MAE X_out (physics, last error held)</source>
        <translation>MAE X_out（机理，保持上一误差）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="415"/>
        <source>MAE T_out (PGRL-CC)</source>
        <translation>MAE T_out（PGRL-CC）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="415"/>
        <source>MAE T_out (last value held)</source>
        <translation>MAE T_out（保持上一测量值）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="416"/>
        <source>MAE T_out (physics, last error held)</source>
        <translation>MAE T_out（机理，保持上一误差）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="443"/>
        <source>model (nothing extended)</source>
        <translation>模型（未扩展）</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="445"/>
        <source>starting model</source>
        <translation>初始模型</translation>
    </message>
    <message>
        <location filename="../widgets/discovery/DiscoverPanel.cpp" line="446"/>
        <source>extended model</source>
        <translation>扩展后的模型</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::ErrorText</name>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="22"/>
        <source>expected %1 fields as in the header, found %2</source>
        <translation>表头有 %1 个字段，此行有 %2 个</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="24"/>
        <source>expected %1 fields as in the header, found %2 (wrong delimiter?)</source>
        <translation>表头有 %1 个字段，此行有 %2 个（分隔符不对？）</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="31"/>
        <source>the folder holds no *.csv batch files</source>
        <translation>文件夹中没有 *.csv 批次文件</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="37"/>
        <source>the file has a header but no data rows</source>
        <translation>文件有表头，但没有数据行</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="40"/>
        <source>missing time; the time index must be complete</source>
        <translation>缺少时间；时间列必须完整</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="57"/>
        <source>%1: no such file or folder</source>
        <translation>%1：文件或文件夹不存在</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="63"/>
        <source>%1: the required column &apos;%2&apos; is missing</source>
        <translation>%1：缺少必需的列“%2”</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="70"/>
        <source>%1, line %2, column %3: text &apos;%4&apos; in the numeric column &apos;%5&apos;</source>
        <translation>%1，第 %2 行，第 %3 列：数值列“%5”中出现文本“%4”</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="77"/>
        <source>%1, line %2, column %3: time does not increase</source>
        <translation>%1，第 %2 行，第 %3 列：时间未递增</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="84"/>
        <source>%1, line %2, column %3: %4</source>
        <translation>%1，第 %2 行，第 %3 列：%4</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="90"/>
        <source>Parameter %1 = %2 lies outside its range [%3, %4]</source>
        <translation>参数 %1 = %2 超出其范围 [%3, %4]</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="96"/>
        <source>No data loaded; open a batch file or folder first.</source>
        <translation>未加载数据；请先打开批次文件或文件夹。</translation>
    </message>
    <message>
        <location filename="../widgets/common/ErrorText.cpp" line="99"/>
        <source>Cancelled by the user.</source>
        <translation>已被用户取消。</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::LineView3D</name>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="73"/>
        <location filename="../widgets/view3d/LineView3D.cpp" line="342"/>
        <source>moisture [% wb]</source>
        <translation>含水率 [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="73"/>
        <location filename="../widgets/view3d/LineView3D.cpp" line="342"/>
        <source>temperature [°C]</source>
        <translation>温度 [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="76"/>
        <location filename="../widgets/view3d/LineView3D.cpp" line="100"/>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="80"/>
        <location filename="../widgets/view3d/LineView3D.cpp" line="325"/>
        <source>Simulate the model to see the parcels.</source>
        <translation>运行模型仿真以查看物料团。</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="84"/>
        <source>Batch</source>
        <translation>批次</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="100"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="196"/>
        <source>drying tube</source>
        <translation>干燥管</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="197"/>
        <source>conveyor</source>
        <translation>输送机</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="198"/>
        <source>winnower</source>
        <translation>风选机</translation>
    </message>
    <message>
        <location filename="../widgets/view3d/LineView3D.cpp" line="315"/>
        <source>%1 s of %2</source>
        <translation>%1 s / %2</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::MainWindow</name>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="39"/>
        <source>DryTwin</source>
        <translation>DryTwin</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="59"/>
        <source>Data</source>
        <translation>数据</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="60"/>
        <source>Model</source>
        <translation>模型</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="23"/>
        <source>open data</source>
        <translation>打开数据</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="26"/>
        <location filename="../widgets/MainWindow.cpp" line="61"/>
        <source>Calibrate</source>
        <translation>标定</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="27"/>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="28"/>
        <source>Learn the correction models (Residual model tab)</source>
        <translation>学习修正模型（残差模型页）</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="29"/>
        <source>Ablation (Residual model tab)</source>
        <translation>消融实验（残差模型页）</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="31"/>
        <source>Run scenario (What-if MPC tab)</source>
        <translation>运行情景（假设分析 MPC 页）</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="42"/>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="72"/>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="81"/>
        <source>Export report</source>
        <translation>导出报告</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="43"/>
        <source>the report needs every step&apos;s result; still to run: %1</source>
        <translation>报告需要每一步的结果；尚需运行：%1</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="48"/>
        <source>cannot create the folder</source>
        <translation>无法创建该文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="56"/>
        <source>DryTwin workbench: data %1, model %2</source>
        <translation>DryTwin 工作台：数据 %1，模型 %2</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="59"/>
        <source>as built in this window (save it with File ▸ Save model as…)</source>
        <translation>本窗口中构建的模型（用 文件 ▸ 模型另存为… 保存）</translation>
    </message>
    <message>
        <source>The report needs every step&apos;s result; still to run: %1.</source>
        <translation>报告需要每一步的结果；尚需运行：%1。</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="75"/>
        <source>Export report into folder</source>
        <translation>将报告导出到文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="85"/>
        <source>Report written: %1</source>
        <translation>报告已写入：%1</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="62"/>
        <source>Residual model</source>
        <translation>残差模型</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="63"/>
        <source>Diagnostics</source>
        <translation>诊断</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowReport.cpp" line="30"/>
        <location filename="../widgets/MainWindow.cpp" line="64"/>
        <source>Discover</source>
        <translation>发现</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="65"/>
        <source>What-if MPC</source>
        <translation>假设分析 MPC</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="66"/>
        <source>3D line</source>
        <translation>三维产线</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="68"/>
        <source>Training</source>
        <translation>培训</translation>
    </message>
    <message>
        <source>No data loaded. File ▸ Open data set…</source>
        <translation>未加载数据。文件 ▸ 打开数据集…</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="72"/>
        <source>&lt;b&gt;Data&lt;/b&gt;: the loaded batches, their rows kept by the cleaning, and every measured channel over time. Select several batches to overlay them; drop files here to open them. Files with other column names open through Column mapping…</source>
        <translation>&lt;b&gt;数据&lt;/b&gt;：已加载的批次、清洗后保留的行，以及每个测量通道随时间的变化。选择多个批次可叠加显示；把文件拖到这里即可打开。列名不同的文件通过“列映射…”打开。</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="76"/>
        <source>&lt;b&gt;Model&lt;/b&gt;: the physics model&apos;s parameters with units and bounds (paper Eqs. 1–19), and its simulation against the measurements. Edit a value to try it; Undo takes it back.</source>
        <translation>&lt;b&gt;模型&lt;/b&gt;：物理模型的参数及其单位和范围（论文公式 1–19），以及模拟与测量的对比。修改数值即可试验；“撤销”可恢复。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Calibrate&lt;/b&gt;: fits the ticked parameters to the data (a global search, then BOBYQA) and gives each its 95 % interval. Stop keeps the best so far.</source>
        <translation>&lt;b&gt;标定&lt;/b&gt;：把勾选的参数拟合到数据（先全局搜索，再 BOBYQA），并给出各自的 95 % 区间。停止时保留目前最优。</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="80"/>
        <source>&lt;b&gt;Calibrate&lt;/b&gt;: fits the ticked parameters to the data (a global search, then a local polish: BOBYQA) and gives each its 95 % interval. Stop keeps the best so far.</source>
        <translation>&lt;b&gt;标定&lt;/b&gt;：将勾选的参数拟合到数据（先全局搜索，再局部精修：BOBYQA），并给出每个参数的 95 % 区间。停止时保留当前最优结果。</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="83"/>
        <source>&lt;b&gt;Residual model&lt;/b&gt;: learns a correction of the physics model from the data (PGRL-CC, paper Eqs. 20–30) and scores it on held-out data beside the comparison models and the two trivial forecasts. Skill below 1 beats both.</source>
        <translation>&lt;b&gt;残差模型&lt;/b&gt;：从数据学习物理模型的修正（PGRL-CC，论文公式 20–30），并在留出数据上与对比模型及两个平凡预测一起评分。预报技巧小于 1 即优于二者。</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="87"/>
        <source>&lt;b&gt;Diagnostics&lt;/b&gt;: the residuals&apos; autocorrelation and spectrum (white noise is what a complete model leaves), where in the operating range the physics model errs, and what its error moves with.</source>
        <translation>&lt;b&gt;诊断&lt;/b&gt;：残差的自相关和频谱（完整的模型只留下白噪声）、物理模型在工况范围内何处出错，以及其误差随什么变化。</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="91"/>
        <source>&lt;b&gt;Discover&lt;/b&gt;: what the simulation gets wrong, the physical cause when one is specific (better on every output it touches, consistent across batches, told apart from its look-alikes), and the gain of the extended model.</source>
        <translation>&lt;b&gt;发现&lt;/b&gt;：模拟哪里不准；当某个物理原因具有特异性时给出它（在其影响的每个输出上都更好、各批次间一致、能与相似原因区分），以及扩展模型的收益。</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="95"/>
        <source>&lt;b&gt;What-if MPC&lt;/b&gt;: a scenario run against the virtual plant once per controller, an MPC on each model that exists and the plant&apos;s own PI loop, with the paper&apos;s Table 2 metrics.</source>
        <translation>&lt;b&gt;假设分析 MPC&lt;/b&gt;：针对虚拟装置，为每个控制器运行一次情景：每个已有模型上的 MPC 以及装置自己的 PI 回路，并给出论文表 2 的指标。</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="99"/>
        <source>&lt;b&gt;3D line&lt;/b&gt;: the drying tube, conveyor and winnower with the material parcels coloured by moisture at the time cursor; the slider moves every plot&apos;s cursor.</source>
        <translation>&lt;b&gt;三维产线&lt;/b&gt;：干燥管、输送机和风选机，物料颗粒按时间光标处的含水率着色；滑块同时移动所有曲线图的光标。</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="102"/>
        <source>&lt;b&gt;Training&lt;/b&gt;: the line runs live for a trainee; the instructor&apos;s window injects faults, freezes the clock and scores the answers.</source>
        <translation>&lt;b&gt;培训&lt;/b&gt;：产线为学员实时运行；教员窗口可注入故障、冻结时钟并为回答评分。</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowData.cpp" line="27"/>
        <source>The data set every tab shows; the others opened in this window stay here</source>
        <translation>各页显示的数据集；在本窗口打开过的其他数据集也保留在这里</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowData.cpp" line="33"/>
        <source>Data set:</source>
        <translation>数据集：</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowData.cpp" line="44"/>
        <source>none loaded</source>
        <translation>未加载</translation>
    </message>
    <message>
        <source>the data changed since the project was saved</source>
        <translation>项目保存后数据已改变</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowData.cpp" line="83"/>
        <source>Project data changed</source>
        <translation>项目数据已改变</translation>
    </message>
    <message>
        <source>The project&apos;s data are not what they were when it was saved (then: %1; now: %2). The results shown were made on the data as saved; run the steps again to update them.</source>
        <translation type="vanished">项目的数据与保存时不同（当时：%1；现在：%2）。显示的结果基于保存时的数据；请重新运行各步骤以更新结果。</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowData.cpp" line="73"/>
        <source>nothing</source>
        <translation>无</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowData.cpp" line="77"/>
        <source>the same batches and rows, %1, hold other values</source>
        <translation>批次和行数相同（%1），但数值已改变</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowData.cpp" line="78"/>
        <source>then: %1; now: %2</source>
        <translation>当时：%1；现在：%2</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowData.cpp" line="80"/>
        <source>The project&apos;s data are not what they were when it was saved (%1). The results shown were made on the data as saved; run the steps again to update them.</source>
        <translation>项目的数据与保存时不同（%1）。显示的结果基于保存时的数据；请重新运行各步骤以更新结果。</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowData.cpp" line="105"/>
        <source>The project&apos;s data could not be opened from %1: its model and saved results are shown. Open the data (File ▸ Open data set folder…) to run anything on them.</source>
        <translation>无法从 %1 打开项目的数据：已显示其模型和保存的结果。请打开数据（文件 ▸ 打开数据集文件夹…）后再运行任何步骤。</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="24"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Map its columns…</source>
        <translation>映射其列…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="27"/>
        <source>Open the column-mapping dialog for the file that was not recognised</source>
        <translation>为未能识别的文件打开列映射对话框</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="72"/>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="75"/>
        <source>%1: %2 %</source>
        <translation>%1：%2 %</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>The line&apos;s commissioning runs are in %1: choose them under &quot;Compare with a reference period&quot; to ask what changed since commissioning.</source>
        <translation>产线的调试运行数据位于 %1：在“与参考期比较”中选择它们，即可查看自调试以来发生了什么变化。</translation>
    </message>
    <message>
        <location filename="../widgets/MainWindow.cpp" line="142"/>
        <source>Opening the recording beside %1; the data-set list at the top right switches back.</source>
        <translation>正在 %1 之外另行打开该记录；用右上角的数据集列表可切换回去。</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="26"/>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="27"/>
        <source>&amp;Open batch file…</source>
        <translation>打开批次文件(&amp;O)…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="28"/>
        <source>Open batch file</source>
        <translation>打开批次文件</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="28"/>
        <source>Batch files (*.csv)</source>
        <translation>批次文件 (*.csv)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="34"/>
        <source>Open data set &amp;folder…</source>
        <translation>打开数据集文件夹(&amp;F)…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="35"/>
        <source>Open data set folder</source>
        <translation>打开数据集文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="40"/>
        <source>Open the bundled &amp;demo</source>
        <translation>打开自带演示数据(&amp;D)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="41"/>
        <source>&amp;Generate virtual-plant data…</source>
        <translation>生成虚拟装置数据(&amp;G)…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="42"/>
        <source>Folder for the virtual plant&apos;s batches</source>
        <translation>虚拟装置批次的文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="51"/>
        <source>Open &amp;model…</source>
        <translation>打开模型(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="52"/>
        <source>Open model</source>
        <translation>打开模型</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="52"/>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="59"/>
        <source>Model files (*.json)</source>
        <translation>模型文件 (*.json)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="57"/>
        <source>Save model &amp;as…</source>
        <translation>模型另存为(&amp;A)…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="59"/>
        <source>Save model</source>
        <translation>保存模型</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="65"/>
        <source>Open &amp;project…</source>
        <translation>打开项目(&amp;P)…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="66"/>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="69"/>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="151"/>
        <source>Open project</source>
        <translation>打开项目</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="66"/>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="76"/>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="86"/>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="53"/>
        <source>DryTwin projects (*.drytwin)</source>
        <translation>DryTwin 项目 (*.drytwin)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="72"/>
        <source>&amp;Save project</source>
        <translation>保存项目(&amp;S)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="75"/>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="80"/>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="85"/>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="89"/>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="52"/>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="71"/>
        <source>Save project</source>
        <translation>保存项目</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="84"/>
        <source>Save project as…</source>
        <translation>项目另存为…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="93"/>
        <source>Export &amp;report…</source>
        <translation>导出报告(&amp;R)…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="94"/>
        <source>Recent projects</source>
        <translation>最近的项目</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="97"/>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="100"/>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="101"/>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="119"/>
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="107"/>
        <source>Ready.</source>
        <translation>就绪。</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowProject.cpp" line="46"/>
        <source>cannot create the folder %1 for the project</source>
        <translation>无法为项目创建文件夹 %1</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowProject.cpp" line="77"/>
        <source>Project saved to %1 (model, results and view)</source>
        <translation>项目已保存到 %1（模型、结果和视图）</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowProject.cpp" line="172"/>
        <source>Saving the project to %1…</source>
        <translation>正在保存项目到 %1…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowProject.cpp" line="229"/>
        <source>The project&apos;s results could not be read (%1); it opens without them.</source>
        <translation>无法读取项目的结果（%1）；项目将不带结果打开。</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowProject.cpp" line="312"/>
        <source>Wait until the running job has finished (or cancel it), then switch the language.</source>
        <translation>请等待当前任务完成（或取消它），然后再切换语言。</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowProject.cpp" line="351"/>
        <source>The training session under way was saved in %1 when the language changed: the instructor window&apos;s Session file ▸ Open session… continues it.</source>
        <translation>切换语言时，进行中的培训会话已保存到 %1：在教员窗口的 会话文件 ▸ 打开会话… 可继续。</translation>
    </message>
    <message>
        <source>The language changes when DryTwin is started again.</source>
        <translation>语言将在 DryTwin 重新启动后生效。</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="123"/>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="124"/>
        <source>&amp;User guide</source>
        <translation>用户指南(&amp;U)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="127"/>
        <source>&amp;About DryTwin</source>
        <translation>关于 DryTwin(&amp;A)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="128"/>
        <source>About DryTwin</source>
        <translation>关于 DryTwin</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowMenus.cpp" line="129"/>
        <source>About &amp;Qt</source>
        <translation>关于 Qt(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowHelp.cpp" line="33"/>
        <source>DryTwin user guide</source>
        <translation>DryTwin 用户指南</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="26"/>
        <source>Column mapping…</source>
        <translation>列映射…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="127"/>
        <source>No data loaded. File ▸ Open data set folder… (or File ▸ Open the bundled demo)</source>
        <translation>未加载数据。文件 ▸ 打开数据集文件夹…（或 文件 ▸ 打开自带演示数据）</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="133"/>
        <source>Loading</source>
        <translation>正在加载</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="134"/>
        <source>Simulating</source>
        <translation>正在模拟</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="135"/>
        <source>Calibrating</source>
        <translation>正在标定</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="136"/>
        <source>Learning the correction models</source>
        <translation>正在学习修正模型</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="137"/>
        <source>Training the LSTM</source>
        <translation>正在训练 LSTM</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="138"/>
        <source>Scoring on the held-out part</source>
        <translation>正在留出部分上评分</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="139"/>
        <source>Discovering</source>
        <translation>正在发现</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="140"/>
        <source>Ablation</source>
        <translation>消融实验</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="141"/>
        <source>What-if scenario</source>
        <translation>假设情景</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="142"/>
        <source>Generating plant data</source>
        <translation>正在生成装置数据</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowStatus.cpp" line="143"/>
        <source>Training session</source>
        <translation>培训会话</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowHelp.cpp" line="43"/>
        <source>&lt;h3&gt;DryTwin %1&lt;/h3&gt;&lt;p&gt;Digital-twin workbench for pneumatic drying lines, implementing the PGRL-CC method.&lt;/p&gt;&lt;table&gt;</source>
        <translation>&lt;h3&gt;DryTwin %1&lt;/h3&gt;&lt;p&gt;气流干燥生产线数字孪生工作台，实现 PGRL-CC 方法。&lt;/p&gt;&lt;table&gt;</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowData.cpp" line="143"/>
        <source>Writing the bundled demo (10 batches of the virtual plant) to %1…</source>
        <translation>正在把自带演示数据（虚拟装置的 10 个批次）写入 %1…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowProject.cpp" line="56"/>
        <location filename="../widgets/mainwindow/MainWindowProject.cpp" line="155"/>
        <location filename="../widgets/mainwindow/MainWindowProject.cpp" line="162"/>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Project saved to %1</source>
        <translation>项目已保存到 %1</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowProject.cpp" line="180"/>
        <source>cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowProject.cpp" line="189"/>
        <source>%1 is not a DryTwin project (%2)</source>
        <translation>%1 不是 DryTwin 项目（%2）</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowScripting.cpp" line="96"/>
        <source>Opening the training session %1…</source>
        <translation>正在打开培训会话 %1…</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowScripting.cpp" line="107"/>
        <source>Training session %1 (its recording is on the Training tab; no data set is loaded for the other tabs)</source>
        <translation>培训会话 %1（其记录显示在“培训”选项卡上；其他选项卡未加载数据集）</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowScripting.cpp" line="111"/>
        <source>The training session %1 could not be opened: %2</source>
        <translation>无法打开培训会话 %1：%2</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="28"/>
        <source>the calibration</source>
        <translation>标定</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="29"/>
        <source>the learnt correction models</source>
        <translation>学习的修正模型</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="30"/>
        <source>the discovery</source>
        <translation>发现结果</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="31"/>
        <source>the what-if run</source>
        <translation>假设分析运行</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="32"/>
        <source>the ablation</source>
        <translation>消融实验</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="33"/>
        <source>the changes to the model</source>
        <translation>对模型的修改</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="34"/>
        <source>the edited scenario</source>
        <translation>编辑过的情景</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="38"/>
        <source>Save the project?</source>
        <translation>保存项目？</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="39"/>
        <source>Not saved in a project yet: %1. Save the project before closing?</source>
        <translation>尚未保存到项目中：%1。关闭前保存项目吗？</translation>
    </message>
    <message>
        <location filename="../widgets/mainwindow/MainWindowUnsaved.cpp" line="40"/>
        <source>, </source>
        <translation>、</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::ModelPanel</name>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="51"/>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="51"/>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="51"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="51"/>
        <source>Lower</source>
        <translation>下限</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="51"/>
        <source>Upper</source>
        <translation>上限</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="51"/>
        <source>Source</source>
        <translation>来源</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="51"/>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="54"/>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="55"/>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="63"/>
        <source>Physics switches</source>
        <translation>物理开关</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="65"/>
        <source>clamp water activity (Eq. 2)</source>
        <translation>限制水分活度（式 2）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="65"/>
        <source>bound-water latent heat (Eq. 4)</source>
        <translation>结合水潜热（式 4）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="66"/>
        <source>moisture-dependent heat capacity (Eq. 3)</source>
        <translation>随含水率变化的比热（式 3）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="67"/>
        <source>consistent energy balance (Eqs. 12, 14, 19; off: as printed)</source>
        <translation>一致的能量平衡（式 12、14、19；关闭：按原文）</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="83"/>
        <source>Simulate</source>
        <translation>仿真</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="84"/>
        <source>Run the physics model over every batch with these parameters</source>
        <translation>用这些参数对每个批次运行机理模型</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="91"/>
        <source>Double-click a value to edit it; it is checked against its bounds.</source>
        <translation>双击数值进行编辑；将按其上下限检查。</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="103"/>
        <source>Batch:</source>
        <translation>批次：</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="107"/>
        <source>X_out [% wb]</source>
        <translation>X_out [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="108"/>
        <source>T_out [°C]</source>
        <translation>T_out [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="109"/>
        <source>X_HDT [% wb]</source>
        <translation>X_HDT [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="110"/>
        <source>T_HDT [°C]</source>
        <translation>T_HDT [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="147"/>
        <source>%1 must lie in [%2, %3] %4; it stays %5.</source>
        <translation>%1 必须在 [%2, %3] %4 之内；保持为 %5。</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="208"/>
        <location filename="../widgets/model/ModelPanel.cpp" line="216"/>
        <source>measured</source>
        <translation>实测</translation>
    </message>
    <message>
        <location filename="../widgets/model/ModelPanel.cpp" line="228"/>
        <source>physics model</source>
        <translation>机理模型</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::ModelStateBar</name>
    <message>
        <location filename="../widgets/common/ModelStateBar.cpp" line="16"/>
        <source>Retrain the stale models</source>
        <translation>重新训练过期模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/ModelStateBar.cpp" line="17"/>
        <source>Learn the correction models again on the loaded data, with the settings they were last learnt with</source>
        <translation>用上次的设置，在已加载的数据上重新学习修正模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/ModelStateBar.cpp" line="24"/>
        <source>The model every tab works with: whether the physics model is calibrated or extended, and for each learnt correction model the data it was learnt on, or why it no longer fits the physics model (stale) and must be learnt again.</source>
        <translation>各页使用的模型：物理模型是否已标定或扩展；每个学习得到的修正模型是在哪些数据上学习的，或者为何它已不再匹配物理模型（过期）而必须重新学习。</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::MpcPanel</name>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="50"/>
        <source>Open scenario…</source>
        <translation>打开情景…</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="54"/>
        <source>The scenario as JSON (schema in docs/mpc.md): setpoint steps, input steps and ramps, hidden mechanisms switched on mid-run, noise. Edits are checked when you run.</source>
        <translation>以 JSON 表示的情景（格式见 docs/mpc.md）：设定值阶跃、输入阶跃与斜坡、运行中途开启的隐藏机理、噪声。运行时检查修改。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="66"/>
        <source>Run scenario</source>
        <translation>运行情景</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="69"/>
        <source>Show the horizon the controllers predicted at this decision</source>
        <translation>显示控制器在此决策时刻预测的时域</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="70"/>
        <source>Runs the scenario against the virtual plant once per controller.</source>
        <translation>对虚拟装置逐个控制器运行该情景。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="75"/>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>IAE [%·s]</source>
        <translation type="vanished">IAE [%·s]</translation>
    </message>
    <message>
        <source>Effort [K²]</source>
        <translation type="vanished">控制动作量 [K²]</translation>
    </message>
    <message>
        <source>Violations [%]</source>
        <translation type="vanished">越限 [%]</translation>
    </message>
    <message>
        <source>IAE [% wb·s]</source>
        <translation type="vanished">IAE [% 湿基·s]</translation>
    </message>
    <message>
        <source>Solve median [ms]</source>
        <translation type="vanished">求解时间中位数 [ms]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="76"/>
        <source>Fallbacks</source>
        <translation>回退次数</translation>
    </message>
    <message>
        <source>Model gain [%/K]</source>
        <translation type="vanished">模型增益 [%/K]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="75"/>
        <source>IAE
[% wb·s]</source>
        <translation>IAE
[% 湿基·s]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="75"/>
        <source>Effort
[K²]</source>
        <translation>控制动作量
[K²]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="75"/>
        <source>Violations
[%]</source>
        <translation>越限
[%]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="76"/>
        <source>Solve median
[ms]</source>
        <translation>求解时间中位数
[ms]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="76"/>
        <source>Model gain
[%/K]</source>
        <translation>模型增益
[%/K]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="80"/>
        <source>IAE: the outlet moisture&apos;s distance from its setpoint, summed over every second of the run (% wb × s); smaller is tighter control.</source>
        <translation>IAE：出口含水率与设定值之差，按运行的每一秒累加（% 湿基 × s）；越小控制越紧。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="82"/>
        <source>Effort: the squared moves of the hot-air setpoint, summed (K²); smaller is gentler on the burner.</source>
        <translation>控制动作量：热风设定值各次调整的平方和（K²）；越小对燃烧器越温和。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="84"/>
        <source>Share of the run with the product outside its specification band.</source>
        <translation>产品超出规格带的运行时间占比。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="85"/>
        <source>Median time the controller took to decide, per decision.</source>
        <translation>控制器每次决策所用时间的中位数。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="86"/>
        <source>Decisions where the optimiser failed and the controller kept its last move, of all decisions.</source>
        <translation>优化器求解失败、控制器沿用上一步动作的决策次数 / 全部决策次数。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="88"/>
        <source>How much X_out changes per kelvin of hot air in the controller&apos;s model (median); compare with the plant&apos;s own gain below.</source>
        <translation>控制器模型中热风每变化 1 K 时 X_out 的变化量（中位数）；可与下方装置自身的增益比较。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="91"/>
        <source>X_out, true [% wb]</source>
        <translation>X_out 真实值 [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="92"/>
        <source>T_hot setpoint [°C]</source>
        <translation>T_hot 设定值 [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="107"/>
        <source>Form</source>
        <translation>表单</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="108"/>
        <source>JSON</source>
        <translation>JSON</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="119"/>
        <source>prediction at</source>
        <translation>预测时刻</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="174"/>
        <source>Open scenario</source>
        <translation>打开情景</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="174"/>
        <source>Scenarios (*.json)</source>
        <translation>情景 (*.json)</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="185"/>
        <source>Run a scenario to see each controller&apos;s outlet moisture and hot-air setpoint</source>
        <translation>运行一个情景，可看到各控制器的出口含水率和热风设定值</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="202"/>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="203"/>
        <source>the scenario</source>
        <translation>该情景</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="208"/>
        <source>The run was cancelled; the results below are from the last complete run.</source>
        <translation>运行已取消；下方结果来自上一次完整运行。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="209"/>
        <source>The run was cancelled.</source>
        <translation>运行已取消。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="213"/>
        <source>%1
The results below are from the last complete run.</source>
        <translation>%1
下方结果来自上一次完整运行。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="221"/>
        <source>%1: its model&apos;s gain has the other sign than the plant&apos;s, so it steers the hot air the wrong way.</source>
        <translation>%1：其模型的增益与装置的符号相反，因此它把热风往错误的方向调。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="226"/>
        <source>%1: its model&apos;s gain is %2 times the plant&apos;s; it underrates the hot air&apos;s effect, so it over-acts (the setpoint swings towards its limits).</source>
        <translation>%1：其模型的增益是装置的 %2 倍；它低估了热风的作用，因此调节过度（设定值摆向其上下限）。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="231"/>
        <source>%1: its model&apos;s gain is %2 times the plant&apos;s; it overrates the hot air&apos;s effect, so it acts too little.</source>
        <translation>%1：其模型的增益是装置的 %2 倍；它高估了热风的作用，因此调节不足。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="242"/>
        <source>%1 (problems in the form: %2)</source>
        <translation>%1（表单中的问题：%2 个）</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="256"/>
        <source>a value or key the scenario&apos;s schema does not accept</source>
        <translation>情景的格式不接受的值或键</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="257"/>
        <source>The scenario&apos;s JSON: %1</source>
        <translation>情景 JSON：%1</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="258"/>
        <source>The scenario&apos;s JSON, line %1: %2</source>
        <translation>情景 JSON 第 %1 行：%2</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="263"/>
        <source>Run is off until this is fixed: %1</source>
        <translation>修正以下问题前无法运行：%1</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="276"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="319"/>
        <source>Not run: %1</source>
        <translation>未运行：%1</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="335"/>
        <source>Cannot write %1</source>
        <translation>无法写入 %1</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="353"/>
        <source>Choose at least one controller.</source>
        <translation>请至少选择一个控制器。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="357"/>
        <source>Running…</source>
        <translation>正在运行…</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="369"/>
        <source>Contract key: %1</source>
        <translation>接口代码：%1</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="372"/>
        <source>%1 (stale, being learnt again)</source>
        <translation>%1（过期，正在重新学习）</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="374"/>
        <source>Learnt before %1; it is being learnt again now.</source>
        <translation>在%1之前学习；现在正在重新学习。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="376"/>
        <source>%1 (stale)</source>
        <translation>%1（过期）</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="377"/>
        <source>Learnt before %1: retrain it to run it.</source>
        <translation>学习于以下变化之前：%1；需重新训练才能运行。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="379"/>
        <source>%1 (not learnt)</source>
        <translation>%1（未学习）</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="380"/>
        <source>Learn the correction models on the Residual model tab to run it.</source>
        <translation>在残差模型页学习修正模型后才能运行它。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="402"/>
        <source>predicted at %1 s</source>
        <translation>在 %1 s 时的预测</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="412"/>
        <source>skipped</source>
        <translation>已跳过</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="413"/>
        <source>the model holds no such prediction model</source>
        <translation>模型中没有这种预测模型</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="426"/>
        <source>Decisions that kept the previous plan (the model saw no effect of the hot air, or the solve failed); the last reason: %1</source>
        <translation>沿用上一计划的决策次数（模型看不到热风的作用，或求解失败）；最近一次的原因：%1</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="440"/>
        <source>setpoint</source>
        <translation>设定值</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="449"/>
        <source>band</source>
        <translation>允许带</translation>
    </message>
    <message>
        <source>%1 predicted at %2 s</source>
        <translation>%1 在 %2 s 时的预测</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/MpcPanel.cpp" line="490"/>
        <source>%1. IAE and violations on the product&apos;s true outlet moisture; the plant&apos;s own gain is %2 % wb/K.</source>
        <translation>%1。IAE 与越限按产品真实出口含水率计；装置自身增益为 %2 % 湿基/K。</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::PlotStack</name>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="214"/>
        <source>Ctrl+click: cursor A, Shift+click: cursor B, Alt+click: time cursor; drag to zoom, right click to zoom out, middle drag to pan</source>
        <translation>Ctrl+单击：游标 A，Shift+单击：游标 B，Alt+单击：时间游标；拖动放大，右键缩小，中键拖动平移</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="90"/>
        <source>Export…</source>
        <translation>导出…</translation>
    </message>
    <message>
        <source>Save these plots as PNG, SVG or PDF</source>
        <translation>将这些图表保存为 PNG、SVG 或 PDF</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="91"/>
        <source>Save these plots as PNG, SVG or PDF, or their data as CSV</source>
        <translation>把这些曲线图保存为 PNG、SVG 或 PDF，或把数据保存为 CSV</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="198"/>
        <source>time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStack.cpp" line="279"/>
        <source>No data yet</source>
        <translation>尚无数据</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackCursors.cpp" line="105"/>
        <source>A %1</source>
        <translation>A %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackCursors.cpp" line="108"/>
        <source>B %1</source>
        <translation>B %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackCursors.cpp" line="111"/>
        <source>Δx %1</source>
        <translation>Δx %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackCursors.cpp" line="115"/>
        <source>%1: Δ %2</source>
        <translation>%1：Δ %2</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackCursors.cpp" line="119"/>
        <source>time cursor %1 s</source>
        <translation>时间游标 %1 s</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackExport.cpp" line="90"/>
        <source>cannot write %1</source>
        <translation>无法写入 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackExport.cpp" line="118"/>
        <source>unknown format &apos;%1&apos;: use .png, .svg, .pdf or .csv</source>
        <translation>未知格式“%1”：请使用 .png、.svg、.pdf 或 .csv</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackExport.cpp" line="156"/>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF (*.pdf);;Data as CSV (*.csv)</source>
        <translation>PNG 图像 (*.png);;SVG 图形 (*.svg);;PDF (*.pdf);;CSV 数据 (*.csv)</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackExport.cpp" line="68"/>
        <source>DryTwin plots</source>
        <translation>DryTwin 图表</translation>
    </message>
    <message>
        <source>unknown format &apos;%1&apos;: use .png, .svg or .pdf</source>
        <translation>未知格式“%1”：请使用 .png、.svg 或 .pdf</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackExport.cpp" line="155"/>
        <source>Export plots</source>
        <translation>导出图表</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF (*.pdf)</source>
        <translation>PNG 图像 (*.png);;SVG 矢量图 (*.svg);;PDF (*.pdf)</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackExport.cpp" line="162"/>
        <source>Export failed: %1</source>
        <translation>导出失败：%1</translation>
    </message>
    <message>
        <location filename="../widgets/common/PlotStackExport.cpp" line="164"/>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::ResidualPanel</name>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="35"/>
        <source>chosen by validation (16, 32, 60)</source>
        <translation>由验证选择（16、32、60）</translation>
    </message>
    <message>
        <source>Eq. 30: constrained fit with certificate</source>
        <translation>式 30：带证书的约束拟合</translation>
    </message>
    <message>
        <source>eigenvalues pulled in after the fit</source>
        <translation>拟合后将特征值收缩</translation>
    </message>
    <message>
        <source>orthogonal projection P⊥ (Eq. 27)</source>
        <translation>正交投影 P⊥（式 27）</translation>
    </message>
    <message>
        <source>Train PGRL-CC and the baselines</source>
        <translation>训练 PGRL-CC 及基线模型</translation>
    </message>
    <message>
        <source>residual lags</source>
        <translation>残差滞后阶数</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="56"/>
        <source>stability</source>
        <translation>稳定性</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="60"/>
        <source>Trains on the chronological 70 % and evaluates on the rest; settings are chosen inside the training part.</source>
        <translation>按时间顺序用前 70 % 训练，其余部分评估；设置在训练部分内选定。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="63"/>
        <source>Run a What-if MPC scenario to compare each model&apos;s steady gain of X_out to the hot air with the plant&apos;s.</source>
        <translation>运行一次假设 MPC 情景，即可将各模型 X_out 对热风的稳态增益与装置的增益比较。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="66"/>
        <source>Model</source>
        <translation>模型</translation>
    </message>
    <message>
        <source>MAE X_out [% wb]</source>
        <translation>MAE X_out [% 湿基]</translation>
    </message>
    <message>
        <source>R² X_out</source>
        <translation>R² X_out</translation>
    </message>
    <message>
        <source>MAE T_out [°C]</source>
        <translation>MAE T_out [°C]</translation>
    </message>
    <message>
        <source>skill 1 step</source>
        <translation>1 步预报技巧</translation>
    </message>
    <message>
        <source>skill 30 steps</source>
        <translation>30 步预报技巧</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="78"/>
        <source>imaginary part</source>
        <translation>虚部</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="79"/>
        <source>real part</source>
        <translation>实部</translation>
    </message>
    <message>
        <source>skill: MAE over the better reference [-]</source>
        <translation>预报技巧：MAE 与较优参考之比 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="84"/>
        <source>forecast horizon [steps of 1 s]</source>
        <translation>预测步长 [1 s 步]</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="87"/>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="118"/>
        <source>Ablation (paper Table 3)</source>
        <translation>消融实验（论文表 3）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="88"/>
        <source>Train and evaluate every variant of Table 3 on this model (a few minutes)</source>
        <translation>在此模型上训练并评估表 3 的每个变体（需几分钟）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="90"/>
        <source>Variant</source>
        <translation>变体</translation>
    </message>
    <message>
        <source>MAE X_out, extrapolation</source>
        <translation>MAE X_out（外推）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="38"/>
        <source>guaranteed stable (fit under a stability certificate)</source>
        <translation>保证稳定（在稳定性证书约束下拟合）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="39"/>
        <source>stabilised after the fit (eigenvalues pulled in)</source>
        <translation>拟合后再稳定化（特征值拉回）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="40"/>
        <source>Paper Eq. 30: the correction model&apos;s state matrix A is fitted under the constraint α²P − AᵀPA ≻ 0 with a certificate P; the alternative pulls A&apos;s eigenvalues inside the unit circle after an unconstrained fit.</source>
        <translation>论文公式 30：修正模型的状态矩阵 A 在约束 α²P − AᵀPA ≻ 0（证书 P）下拟合；另一种做法是先无约束拟合，再把 A 的特征值拉回单位圆内。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="43"/>
        <source>keep the correction out of the hot-air direction</source>
        <translation>修正不进入热风方向</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="44"/>
        <source>Paper Eq. 27: the orthogonal projection P⊥ removes from the correction what the manipulated input explains, so that the control gain stays the physics model&apos;s.</source>
        <translation>论文公式 27：正交投影 P⊥ 从修正中去掉操纵输入所能解释的部分，使控制增益保持为物理模型的增益。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="48"/>
        <source>Learn the correction models</source>
        <translation>学习修正模型</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="49"/>
        <source>Trains PGRL-CC (paper Eqs. 20–30) on the chronological 70 % of the data, and the two models it is compared with: the input-only correction and an LSTM</source>
        <translation>在按时间顺序的前 70 % 数据上训练 PGRL-CC（论文公式 20–30）及两个对比模型：仅输入修正和 LSTM</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="53"/>
        <source>How many past seconds of the error the correction model sees (paper: residual lags)</source>
        <translation>修正模型能看到的过去误差秒数（论文：残差滞后阶数）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="55"/>
        <source>memory of the error [s]</source>
        <translation>误差记忆 [s]</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="66"/>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="90"/>
        <source>MAE X_out
[% wb]</source>
        <translation>MAE X_out
[% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="66"/>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="90"/>
        <source>R² X_out
[-]</source>
        <translation>R² X_out
[-]</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="67"/>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="91"/>
        <source>MAE T_out
[°C]</source>
        <translation>MAE T_out
[°C]</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="67"/>
        <source>skill
1 step</source>
        <translation>预报技巧
1 步</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="67"/>
        <source>skill
30 steps</source>
        <translation>预报技巧
30 步</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="69"/>
        <source>Mean absolute error of the outlet moisture on the held-out part.</source>
        <translation>留出部分上出口含水率的平均绝对误差。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="70"/>
        <source>R²: the share of the outlet moisture&apos;s variation the model explains (1: all; below 0: worse than the mean).</source>
        <translation>R²：模型解释的出口含水率变化所占比例（1：全部；低于 0：不如均值）。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="72"/>
        <source>Mean absolute error of the outlet temperature on the held-out part.</source>
        <translation>留出部分上出口温度的平均绝对误差。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="73"/>
        <source>Skill one second ahead: the model&apos;s error over the better of two simple forecasts; below 1 it beats both.</source>
        <translation>提前 1 秒的预报技巧：模型误差除以两个简单预测中较好者的误差；小于 1 即优于二者。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="75"/>
        <source>Skill 30 seconds ahead, alike.</source>
        <translation>提前 30 秒的预报技巧，含义相同。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="81"/>
        <source>skill [-]</source>
        <translation>预报技巧 [-]</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="82"/>
        <source>Skill: a model&apos;s MAE over the better of the two reference forecasts at that horizon; below 1 it beats both</source>
        <translation>预报技巧：模型在该步长上的 MAE 除以两个参考预测中较好者的 MAE；小于 1 即优于二者</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="91"/>
        <source>MAE X_out,
extrapolation</source>
        <translation>MAE X_out，
外推</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="226"/>
        <source>Learn the correction models to see the eigenvalues of their state matrix</source>
        <translation>学习修正模型后可看到其状态矩阵的特征值</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="227"/>
        <source>Learn the correction models to see their skill by forecast horizon</source>
        <translation>学习修正模型后可看到其随预测步长的预报技巧</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="117"/>
        <source>Held-out accuracy</source>
        <translation>留出集精度</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="237"/>
        <source>Learnt. Scoring the models on the held-out part…</source>
        <translation>已学习。正在留出部分上评估模型…</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="184"/>
        <source>%1 %2 (%3 %)</source>
        <translation>%1 %2（%3 %）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="191"/>
        <source>Steady gain of X_out to the hot-air setpoint [% wb per K] at the scenario&apos;s start: the plant (open-loop step test) %1; each model as its MPC saw it, and how far from the plant&apos;s: %2. A learnt residual&apos;s response to the setpoint plan comes from the physics model, since data under the plant&apos;s own loop cannot tell it from the disturbances the loop answered.</source>
        <translation>情景起点处 X_out 对热风设定值的稳态增益 [% 湿基/K]：装置（开环阶跃试验）%1；各模型在其 MPC 中的增益及与装置的偏差：%2。学习得到的残差对设定值计划的响应取自物理模型，因为装置自身闭环下的数据无法将其与闭环所应对的扰动区分开。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="233"/>
        <source>Training…</source>
        <translation>正在训练…</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="238"/>
        <source>Learnt. Their scores on the held-out part come next: %1.</source>
        <translation>已学习。接下来在留出部分上评估：%1。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="240"/>
        <source>Learnt: the eigenvalues are drawn once the models are scored on the held-out part</source>
        <translation>已学习：模型在留出部分上评估后绘出特征值</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="242"/>
        <source>Learnt: the skill curves are drawn once the models are scored on the held-out part</source>
        <translation>已学习：模型在留出部分上评估后绘出技巧曲线</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="257"/>
        <source>Learn the correction models on %1: they train on the chronological 70 % and are scored on the rest.</source>
        <translation>在 %1 上学习修正模型：用按时间顺序的前 70 % 训练，其余部分评分。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="260"/>
        <source>Open a data set first (File ▸ Open data set folder…, or the bundled demo).</source>
        <translation>请先打开数据集（文件 ▸ 打开数据集文件夹…，或自带演示数据）。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="283"/>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="444"/>
        <source>Key: %1</source>
        <translation>代码：%1</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="295"/>
        <source>skill 1 (ties the better reference)</source>
        <translation>预报技巧 1（与较优参考持平）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="305"/>
        <source>unit circle</source>
        <translation>单位圆</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="319"/>
        <source>A unconstrained (ρ = %1)</source>
        <translation>无约束 A（ρ = %1）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="326"/>
        <source>A with Eq. 30 (ρ = %1)</source>
        <translation>式 30 约束后的 A（ρ = %1）</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="364"/>
        <source> Slowest contraction of A: %1 per step (half-life %2 s).</source>
        <translation> A 的最慢收缩：每步 %1（半衰期 %2 s）。</translation>
    </message>
    <message>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="369"/>
        <source>On %1, held-out part: %2 rows. Skill below 1 beats both reference predictors (the last measurement held, and the physics model with its last error held). R² below 0 means a model predicts worse than the batch&apos;s mean (hover an R² for what it says).</source>
        <translation>数据 %1，留出部分：%2 行。预报技巧小于 1 表示优于两个参考预测（保持最后测量值；物理模型保持最后误差）。R² 小于 0 表示模型预测比批次均值还差（鼠标悬停在 R² 上可看说明）。</translation>
    </message>
    <message>
        <source>Held-out part: %1 rows. Skill below 1 beats both reference predictors (the last measurement held, and the PBM with its last error held).</source>
        <translation>留出部分：%1 行。预报技巧低于 1 表示优于两个参考预测器（保持最后一次测量值，以及保持最后误差的 PBM）。</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::ScenarioForm</name>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="82"/>
        <source>distributed (realistic line)</source>
        <translation>分布式（真实产线）</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="83"/>
        <source>lumped (the model&apos;s own equations)</source>
        <translation>集总式（模型自身的方程）</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="85"/>
        <source>realistic (noise, lags, faults)</source>
        <translation>真实（噪声、滞后、故障）</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="86"/>
        <source>ideal</source>
        <translation>理想</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="91"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="95"/>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="99"/>
        <source> % wb</source>
        <translation> % 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="101"/>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="102"/>
        <source>Plant</source>
        <translation>装置</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="103"/>
        <source>Instruments</source>
        <translation>仪表</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="104"/>
        <source>Random seed</source>
        <translation>随机种子</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="105"/>
        <source>Scored length</source>
        <translation>评分时长</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="108"/>
        <source>Initial X_out setpoint</source>
        <translation>初始 X_out 设定值</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="109"/>
        <source>Specification band ±</source>
        <translation>规格带 ±</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="110"/>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="111"/>
        <source>at [s]</source>
        <translation>时刻 [s]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="110"/>
        <source>setpoint to [% wb]</source>
        <translation>设定值变为 [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="111"/>
        <source>input</source>
        <translation>输入</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="111"/>
        <source>over [s]</source>
        <translation>历时 [s]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="111"/>
        <source>to</source>
        <translation>变为</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="112"/>
        <source>hidden cause</source>
        <translation>隐藏原因</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="112"/>
        <source>strength</source>
        <translation>强度</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="112"/>
        <source>from [s]</source>
        <translation>起始 [s]</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="123"/>
        <source>Add</source>
        <translation>添加</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="124"/>
        <source>Remove</source>
        <translation>删除</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="143"/>
        <source>Setpoint steps</source>
        <translation>设定值阶跃</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="151"/>
        <source>Input changes (a ramp when &quot;over&quot; &gt; 0)</source>
        <translation>输入变化（“历时” &gt; 0 时为斜坡）</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="154"/>
        <source>Hidden causes in the plant (no controller knows them)</source>
        <translation>装置中的隐藏原因（控制器均不知道）</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="157"/>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="425"/>
        <source>The scenario as a form; the JSON tab shows the same scenario as text.</source>
        <translation>以表单显示的情景；JSON 页以文本显示同一情景。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="233"/>
        <source>Row %1: enter a number.</source>
        <translation>第 %1 行：请输入数字。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="240"/>
        <source>Step %1: the time cannot be negative.</source>
        <translation>阶跃 %1：时间不能为负。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="244"/>
        <source>Step %1 at %2 s comes after the scored length (%3 s): move it earlier or lengthen the run.</source>
        <translation>阶跃 %1 在 %2 s，晚于评分时长（%3 s）：请提前该阶跃或延长运行时间。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="251"/>
        <source>Step %1 at %2 s comes before the step above it (%3 s): list the steps in time order.</source>
        <translation>阶跃 %1 在 %2 s，早于上一行的阶跃（%3 s）：请按时间顺序排列。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="263"/>
        <source>Step %1: a setpoint of %2 % wb lies outside %3–%4 % wb.</source>
        <translation>阶跃 %1：设定值 %2 % 湿基超出 %3–%4 % 湿基。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="276"/>
        <source>Change %1: the time cannot be negative.</source>
        <translation>变化 %1：时间不能为负。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="280"/>
        <source>Change %1 at %2 s comes after the scored length (%3 s): move it earlier or lengthen the run.</source>
        <translation>变化 %1 在 %2 s，晚于评分时长（%3 s）：请提前该变化或延长运行时间。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="288"/>
        <source>Change %1: a ramp lasts 0 to %2 s (the scored length).</source>
        <translation>变化 %1：斜坡历时应在 0 到 %2 s（评分时长）之间。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="300"/>
        <source>Change %1: %2 lies outside %3–%4 for %5.</source>
        <translation>变化 %1：%2 超出 %5 的范围 %3–%4。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="316"/>
        <source>Hidden cause %1 (%2) is listed twice.</source>
        <translation>隐藏原因 %1（%2）重复列出。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="326"/>
        <source>Hidden cause %1 (%2): a strength of %3 lies outside 0–%4 %5.</source>
        <translation>隐藏原因 %1（%2）：强度 %3 超出 0–%4 %5。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="336"/>
        <source>Hidden cause %1: the time cannot be negative.</source>
        <translation>隐藏原因 %1：时间不能为负。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="340"/>
        <source>Hidden cause %1 from %2 s starts after the scored length (%3 s): move it earlier or lengthen the run.</source>
        <translation>隐藏原因 %1 从 %2 s 开始，晚于评分时长（%3 s）：请提前或延长运行时间。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="349"/>
        <source>Shorter than the scenario below: something happens at %1 s. Lengthen the run to at least %1 s, or move that entry.</source>
        <translation>比下面的情景短：%1 s 时还有事件。请将运行时间延长到至少 %1 s，或移动该条目。</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="403"/>
        <source>%1; strength in %2</source>
        <translation>%1；强度单位 %2</translation>
    </message>
    <message>
        <location filename="../widgets/mpc/ScenarioForm.cpp" line="419"/>
        <source>The JSON tab&apos;s text is not a scenario the form can show (%1); fix it there.</source>
        <translation>JSON 页的文本不是表单可显示的情景（%1）；请在那里修改。</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::Series</name>
    <message>
        <location filename="../widgets/common/Series.cpp" line="18"/>
        <source>T_hot [°C]</source>
        <translation>T_hot [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="20"/>
        <source>feed [kg/h]</source>
        <translation>进料 [kg/h]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="22"/>
        <source>X_in [% wb]</source>
        <translation>X_in [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="24"/>
        <source>T_amb [°C]</source>
        <translation>T_amb [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="26"/>
        <source>RH [%]</source>
        <translation>相对湿度 [%]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="28"/>
        <source>X_HDT [% wb]</source>
        <translation>X_HDT [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="30"/>
        <source>X_out [% wb]</source>
        <translation>X_out [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/common/Series.cpp" line="32"/>
        <source>T_out [°C]</source>
        <translation>T_out [°C]</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::TrainingPanel</name>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="63"/>
        <source>The line&apos;s conditions: initial levels, load changes, seed (docs/mpc.md)</source>
        <translation>产线条件：初始水平、负荷变化、随机种子（docs/mpc.md）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="64"/>
        <source>Start session</source>
        <translation>开始会话</translation>
    </message>
    <message>
        <source>Instructor view</source>
        <translation>教员视图</translation>
    </message>
    <message>
        <source>Shows the instructor&apos;s controls, the faults, the true moisture and the score; hide it before handing the screen to the trainee</source>
        <translation>显示教员的控制、故障、真实含水率和得分；将屏幕交给学员前请隐藏</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="67"/>
        <source>Instructor window…</source>
        <translation>教员窗口…</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="68"/>
        <source>Opens the instructor&apos;s window: clock, snapshots, faults, the true moisture and the score. Not on the trainee&apos;s screen.</source>
        <translation>打开教员窗口：时钟、快照、故障、真实水分和得分。不显示在学员屏幕上。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="70"/>
        <source>No session</source>
        <translation>无会话</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="79"/>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="86"/>
        <source> % wb</source>
        <translation> % 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="88"/>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="97"/>
        <source>Operator</source>
        <translation>操作员</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="99"/>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="103"/>
        <source>X_out setpoint</source>
        <translation>X_out 设定值</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="104"/>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="108"/>
        <source>Diagnose the recording…</source>
        <translation>诊断记录…</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="109"/>
        <source>Saves what the line recorded so far as a batch file and opens it, so that the Discover tab can show what the model gets wrong</source>
        <translation>将产线至今的记录保存为批次文件并打开，以便“发现”页显示模型哪里出错</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="112"/>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="92"/>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="196"/>
        <source>No fault</source>
        <translation>无故障</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="116"/>
        <source>Name the cause</source>
        <translation>给出原因</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="119"/>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="77"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="120"/>
        <source>Stops the line&apos;s clock while you think; press again to continue</source>
        <translation>思考时暂停产线时钟；再按一次继续</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="121"/>
        <source>Trainee</source>
        <translation>学员</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="131"/>
        <source>Causes named (session time):</source>
        <translation>已给出的原因（会话时间）：</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="135"/>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="76"/>
        <source>Freeze</source>
        <translation>冻结</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="139"/>
        <source> min</source>
        <translation> 分钟</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="140"/>
        <source>Run ahead</source>
        <translation>快进</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="141"/>
        <source>Runs the line this much further at full speed</source>
        <translation>以最快速度让产线再运行这么久</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="143"/>
        <source>label (default: the time)</source>
        <translation>标签（默认：时间）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="144"/>
        <source>Take snapshot</source>
        <translation>拍摄快照</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="147"/>
        <source>Restore selected</source>
        <translation>恢复所选快照</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="157"/>
        <source> s from now</source>
        <translation> 秒后</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="158"/>
        <source>Inject fault</source>
        <translation>注入故障</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="159"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="182"/>
        <source>Fault</source>
        <translation>故障</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="159"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="184"/>
        <source>Strength</source>
        <translation>强度</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="159"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="186"/>
        <source>Acts from</source>
        <translation>起作用时间</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="159"/>
        <source>Found</source>
        <translation>发现情况</translation>
    </message>
    <message>
        <source>Found after</source>
        <translation>发现用时</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="163"/>
        <source>Save session…</source>
        <translation>保存会话…</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="164"/>
        <source>Open session…</source>
        <translation>打开会话…</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="165"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="208"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="346"/>
        <source>Instructor</source>
        <translation>教员</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="178"/>
        <source>Clock and snapshots</source>
        <translation>时钟与快照</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="190"/>
        <source>Faults</source>
        <translation>故障</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="194"/>
        <source>A session file holds the scenario, every event (faults, snapshots, answers) and the recording as a batch file; reopening replays it to the same data.</source>
        <translation>会话文件包含工况、每个事件（故障、快照、回答）以及作为批次文件的记录；重新打开时会回放得到相同的数据。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="202"/>
        <source>Set instructor password…</source>
        <translation>设置教员密码…</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="203"/>
        <source>Asked before the instructor window opens (empty: no password)</source>
        <translation>打开教员窗口前询问（留空：不设密码）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="209"/>
        <source>New instructor password (empty: none):</source>
        <translation>新的教员密码（留空：无）：</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="216"/>
        <source>Session file</source>
        <translation>会话文件</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="219"/>
        <source>Start a session: the line runs live under its PI loop.</source>
        <translation>开始会话：产线在其 PI 回路下实时运行。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="224"/>
        <source>Two detectors commissioned on healthy runs of this line: the physics model&apos;s error, and a dynamic PCA monitor of the screens&apos; signals. Each alarms when the line leaves its normal (1 % chance of a false alarm over the session)</source>
        <translation>两个检测器在本产线的健康运行数据上调试：物理模型误差，以及画面信号的动态 PCA 监控。产线偏离正常状态时各自报警（整个会话的误报概率为 1 %）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="243"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="258"/>
        <source>X_out [% wb]</source>
        <translation>X_out [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="244"/>
        <source>T_hot [°C]</source>
        <translation>T_hot [°C]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="245"/>
        <source>Feed [kg/h]</source>
        <translation>进料 [kg/h]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="270"/>
        <source>fault began</source>
        <translation>故障开始</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="271"/>
        <source>trainee&apos;s answer</source>
        <translation>学员的回答</translation>
    </message>
    <message>
        <source>fault: %1</source>
        <translation type="vanished">故障：%1</translation>
    </message>
    <message>
        <source>answer: %1</source>
        <translation type="vanished">回答：%1</translation>
    </message>
    <message>
        <source>Feed [t/h]</source>
        <translation>进料 [t/h]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="246"/>
        <source>X_in [% wb]</source>
        <translation>X_in [% 湿基]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="247"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="259"/>
        <source>session time [min]</source>
        <translation>会话时间 [min]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="249"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="266"/>
        <source>band</source>
        <translation>允许带</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="251"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="268"/>
        <source>setpoint</source>
        <translation>设定值</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="252"/>
        <location filename="../widgets/training/TrainingPanel.cpp" line="262"/>
        <source>X_out measured</source>
        <translation>X_out 测量值</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="255"/>
        <source>DryTwin — instructor</source>
        <translation>DryTwin — 教员</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="264"/>
        <source>X_out true</source>
        <translation>X_out 真实值</translation>
    </message>
    <message>
        <source>Monitor T² [-]</source>
        <translation type="vanished">监控 T² [-]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="285"/>
        <source>99 % limit</source>
        <translation>99 % 限值</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="286"/>
        <source>T² of the model&apos;s error</source>
        <translation>模型误差的 T²</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="303"/>
        <source>alarm</source>
        <translation>报警</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="304"/>
        <source>change began</source>
        <translation>变化开始</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="312"/>
        <source>Start a session to see the line run</source>
        <translation>开始会话即可看到产线运行</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="313"/>
        <source>The monitor&apos;s T² shows once it has a minute of the model&apos;s error</source>
        <translation>监测器积累一分钟的模型误差后显示 T²</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="316"/>
        <source>Start a session to see the true outlet moisture beside the measured</source>
        <translation>开始会话即可看到真实出口含水率与测量值的对比</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="418"/>
        <source>Save the session as a folder</source>
        <translation>把会话保存为文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="421"/>
        <source>Session folder (*)</source>
        <translation>会话文件夹 (*)</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="123"/>
        <source>Line monitor: commissioning on healthy runs of this scenario (a few seconds); it then catches up with the line.</source>
        <translation>产线监控：正在用本场景的健康运行进行调试（几秒钟），随后追上产线。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="127"/>
        <source>Line monitor unavailable: %1</source>
        <translation>产线监控不可用：%1</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="129"/>
        <source>Line monitor: normal (as on its commissioning runs).</source>
        <translation>产线监控：正常（与调试运行一致）。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="133"/>
        <source>the model&apos;s error</source>
        <translation>模型误差</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="133"/>
        <source>the screens&apos; signals (PCA)</source>
        <translation>画面信号（PCA）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="136"/>
        <source>&lt;b&gt;Line monitor: ALARM&lt;/b&gt; at %1 (%2) — the line has left its normal; the change began at about %3. Diagnose the recording to name the cause.</source>
        <translation>&lt;b&gt;产线监控：报警&lt;/b&gt;于 %1（%2）——产线已偏离正常状态；变化约始于 %3。请诊断记录以确定原因。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="139"/>
        <source>&lt;b&gt;Line monitor: ALARM&lt;/b&gt; at %1 (%2) — the line has left its normal. Diagnose the recording to name the cause.</source>
        <translation>&lt;b&gt;产线监控：报警&lt;/b&gt;于 %1（%2）——产线已偏离正常状态。请诊断记录以确定原因。</translation>
    </message>
    <message>
        <source>X_out true (instructor)</source>
        <translation>X_out 真实值（教员）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="279"/>
        <source>T_hot setpoint</source>
        <translation>T_hot 设定值</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="280"/>
        <source>T_hot</source>
        <translation>T_hot</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="281"/>
        <source>feed</source>
        <translation>进料</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="282"/>
        <source>X_in</source>
        <translation>X_in</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="283"/>
        <source>T² [-]</source>
        <translation>T² [-]</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="321"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="322"/>
        <source>Stops the replay or the run ahead; the line stays where it got to</source>
        <translation>停止回放或快进；产线停留在已运行到的位置</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="324"/>
        <source>Scenario</source>
        <translation>工况</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="346"/>
        <source>Instructor password:</source>
        <translation>教员密码：</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="349"/>
        <source>Wrong password: the instructor window stays closed.</source>
        <translation>密码错误：教员窗口保持关闭。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="406"/>
        <source>Select a snapshot to restore.</source>
        <translation>请选择要恢复的快照。</translation>
    </message>
    <message>
        <source>Save the session into a folder</source>
        <translation>将会话保存到文件夹</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="427"/>
        <source>Open a training session</source>
        <translation>打开培训会话</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="427"/>
        <source>Sessions (*.json)</source>
        <translation>会话 (*.json)</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="436"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="446"/>
        <source>Recording opened for diagnosis: %1. Run Discover on it, then name the cause here.</source>
        <translation>已打开记录以供诊断：%1。请在其上运行“发现”，然后在此给出原因。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="449"/>
        <source>Recording opened for diagnosis: %1; the line&apos;s commissioning runs are in %2. Run Discover on it, then name the cause here.</source>
        <translation>已打开记录用于诊断：%1；产线的调试运行数据位于 %2。对其运行“发现”，然后在此处指出原因。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="456"/>
        <source>Session saved: %1</source>
        <translation>会话已保存：%1</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="512"/>
        <source>Session started: the line runs under its PI loop. The MPC controllers use the model loaded now.</source>
        <translation>会话已开始：产线在其 PI 回路下运行。MPC 控制器使用当前加载的模型。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="516"/>
        <source>The previous session was saved in %1.</source>
        <translation>上一个会话已保存在 %1。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="530"/>
        <source>Replaying %1…</source>
        <translation>正在回放 %1…</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="555"/>
        <source>%1 (stale: retrain)</source>
        <translation>%1（过期：需重新训练）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanel.cpp" line="556"/>
        <source>%1 (not learnt)</source>
        <translation>%1（未学习）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="66"/>
        <source>Session reopened at %1, frozen: the instructor resumes it.</source>
        <translation>会话已在 %1 处重新打开并冻结：由教员继续。</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="73"/>
        <source>finished</source>
        <translation>已结束</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="73"/>
        <source>FROZEN</source>
        <translation>已冻结</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="73"/>
        <source>running %1×</source>
        <translation>运行中 %1×</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="75"/>
        <source>%1  t = %2 / %3  (%4)</source>
        <translation>%1  t = %2 / %3（%4）</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="76"/>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="77"/>
        <source>Continue</source>
        <translation>继续</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="87"/>
        <source>Setpoint %1 % wb, band ±%2 % wb</source>
        <translation>设定值 %1 % 湿基，允许带 ±%2 % 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="88"/>
        <source>MPC fell back: %1</source>
        <translation>MPC 已回退：%1</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="92"/>
        <source>%1  %2</source>
        <translation>%1  %2</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingPanelFrame.cpp" line="99"/>
        <source>%1 (at %2)</source>
        <translation>%1（于 %2）</translation>
    </message>
    <message>
        <source>not acting yet</source>
        <translation>尚未起作用</translation>
    </message>
    <message>
        <source>not found</source>
        <translation>未发现</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>&lt;b&gt;Score %1 / 100&lt;/b&gt; — faults found %2 of %3, wrong answers %4, product out of the band %5 % of the time (%6 kg)</source>
        <translation>&lt;b&gt;得分 %1 / 100&lt;/b&gt; — 找到故障 %2 / %3，错误回答 %4，产品超出允许带的时间占 %5 %（%6 kg）</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::TrainingRunner</name>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="398"/>
        <source>Setpoint</source>
        <translation>设定值</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="404"/>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="412"/>
        <source>Inject fault</source>
        <translation>注入故障</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="420"/>
        <source>Freeze</source>
        <translation>冻结</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="429"/>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="438"/>
        <source>Snapshot</source>
        <translation>快照</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="444"/>
        <source>Restore</source>
        <translation>恢复</translation>
    </message>
    <message>
        <location filename="../widgets/training/TrainingRunner.cpp" line="450"/>
        <source>Name the cause</source>
        <translation>给出原因</translation>
    </message>
</context>
<context>
    <name>drytwin::widgets::Workbench</name>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="82"/>
        <source>%1 is queued behind the running job</source>
        <translation>%1 已排队，等待当前任务完成</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="97"/>
        <source>%1 was cancelled; nothing changed.</source>
        <translation>%1 已取消；未作任何更改。</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="98"/>
        <source>%1 failed: %2</source>
        <translation>%1 失败：%2</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="111"/>
        <source>%1 (1 batch)</source>
        <translation>%1（1 个批次）</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="112"/>
        <source>%1 (%2 batches)</source>
        <translation>%1（%2 个批次）</translation>
    </message>
    <message>
        <source>%1 changes the physics model that %2 learnt its corrections on: they will no longer match it and are set aside as stale.</source>
        <translation>“%1”会改变 %2 学习修正时所依据的物理模型：它们将不再匹配，并被标为过期。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="106"/>
        <source>%1, then retrain them</source>
        <translation>%1，然后重新训练它们</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="107"/>
        <source>%1 only (retrain later)</source>
        <translation>仅%1（稍后重新训练）</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="128"/>
        <source>Learnt on the present physics model, these no longer match it and are set aside as stale: %1.</source>
        <translation>以下模型是在当前物理模型上学习的，将不再匹配，并被标为过期：%1。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="129"/>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="156"/>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="158"/>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="162"/>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="131"/>
        <source>%1 changes the physics model. </source>
        <translation>“%1”会改变物理模型。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="155"/>
        <source>%1 replaces the physics model.</source>
        <translation>“%1”会替换物理模型。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="156"/>
        <source>%1 adds to the physics model: %2.</source>
        <translation>“%1”向物理模型中加入：%2。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="158"/>
        <source>Refitted with it: %1.</source>
        <translation>同时重新拟合：%1。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="162"/>
        <source>Learnt on the new model and brought with it: %1.</source>
        <translation>在新模型上学习并随之带来：%1。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="178"/>
        <source>Physics model calibrated (%1 fitted to data).</source>
        <translation>物理模型已标定（%1 已拟合到数据）。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="180"/>
        <source>Physics model with its default parameters (not calibrated).</source>
        <translation>物理模型使用默认参数（未标定）。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="187"/>
        <source>Extended by discovery with: %1.</source>
        <translation>已由发现功能扩展：%1。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="193"/>
        <source>%1: not learnt yet.</source>
        <translation>%1：尚未学习。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="196"/>
        <source>%1: learnt.</source>
        <translation>%1：已学习。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="197"/>
        <source>%1: learnt on %2.</source>
        <translation>%1：在 %2 上学习。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="202"/>
        <source>%1: stale, since %2; being learnt again now.</source>
        <translation>%1：已过期，因为%2；正在重新学习。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="205"/>
        <source>%1: stale, since %2; learning it again is queued behind “%3”.</source>
        <translation>%1：已过期，因为%2；重新学习正排在“%3”之后等待。</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchLearntParts.cpp" line="208"/>
        <source>%1: stale, since %2; retrain it to use it.</source>
        <translation>%1：已过期，因为%2；需重新训练才能使用。</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="133"/>
        <source>Read the model</source>
        <translation>读取模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="151"/>
        <source>Loading %1…</source>
        <translation>正在加载 %1…</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="160"/>
        <source>Load %1</source>
        <translation>加载 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="197"/>
        <source>%1: %2 batches, %3 rows, %4 missing cells; the cleaning keeps %5 rows</source>
        <translation>%1：%2 个批次，%3 行，%4 个缺失值；清洗后保留 %5 行</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="223"/>
        <source>Open model %1</source>
        <translation>打开模型 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="227"/>
        <source>Model %1 opened</source>
        <translation>已打开模型 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="228"/>
        <source>model file %1</source>
        <translation>模型文件 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="234"/>
        <source>Save model</source>
        <translation>保存模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="243"/>
        <source>Model saved to %1</source>
        <translation>模型已保存到 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="249"/>
        <source>Set %1</source>
        <translation>设置 %1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="266"/>
        <source>Set the model</source>
        <translation>设置模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="284"/>
        <location filename="../widgets/common/Workbench.cpp" line="307"/>
        <source>Simulate</source>
        <translation>仿真</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="290"/>
        <source>outlet-moisture MAE %1 % wb over all %2 kept rows</source>
        <translation>全部 %2 个保留样本上的出口含水率 MAE %1 % 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="294"/>
        <source>Simulated 1 batch; %1</source>
        <translation>已仿真 1 个批次；%1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="295"/>
        <source>Simulated %1 batches; %2</source>
        <translation>已仿真 %1 个批次；%2</translation>
    </message>
    <message>
        <source>Simulated %1 batches; mean outlet-moisture MAE %2 % wb</source>
        <translation>已仿真 %1 个批次；出口含水率平均 MAE %2 % 湿基</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="325"/>
        <source>Calibration: %1; loss %2 → %3</source>
        <translation>标定：%1；损失 %2 → %3</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="402"/>
        <source> (and %1 more)</source>
        <translation>（另有 %1 个）</translation>
    </message>
    <message>
        <source>the physics model was calibrated after it was learnt</source>
        <translation>学习之后物理模型又经过了标定</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="351"/>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="158"/>
        <source>Learn the correction models</source>
        <translation>学习修正模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="355"/>
        <source>Learnt the correction models (PGRL-CC) and the two comparison models</source>
        <translation>已学习修正模型（PGRL-CC）和两个对比模型</translation>
    </message>
    <message>
        <location filename="../widgets/calibration/CalibrationPanel.cpp" line="166"/>
        <location filename="../widgets/common/Workbench.cpp" line="320"/>
        <source>Calibrate</source>
        <translation>标定</translation>
    </message>
    <message>
        <source>Calibration %1: loss %2 → %3</source>
        <translation>标定 %1：损失 %2 → %3</translation>
    </message>
    <message>
        <source>Train</source>
        <translation>训练</translation>
    </message>
    <message>
        <source>Trained PGRL-CC and the baselines</source>
        <translation>已训练 PGRL-CC 及基线模型</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="370"/>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="160"/>
        <source>Evaluate</source>
        <translation>评估</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="392"/>
        <source>Discover</source>
        <translation>发现</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="392"/>
        <source>Discover against the reference</source>
        <translation>相对参考期发现</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="405"/>
        <source>Discovery: %1</source>
        <translation>发现：%1</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="412"/>
        <source>What-if scenario</source>
        <translation>假设情景</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="427"/>
        <location filename="../widgets/residual/ResidualPanel.cpp" line="159"/>
        <source>Ablation</source>
        <translation>消融实验</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="431"/>
        <source>Ablation: %1 variants trained and evaluated</source>
        <translation>消融实验：已训练并评估 %1 个变体</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="438"/>
        <source>Generate</source>
        <translation>生成</translation>
    </message>
    <message>
        <location filename="../widgets/common/Workbench.cpp" line="441"/>
        <source>Wrote %1 virtual-plant batches to %2</source>
        <translation>已将 %1 个虚拟装置批次写入 %2</translation>
    </message>
    <message>
        <location filename="../widgets/common/WorkbenchDataSets.cpp" line="105"/>
        <source>Queued — waits for “%1”</source>
        <translation>已排队——等待“%1”完成</translation>
    </message>
</context>
</TS>
