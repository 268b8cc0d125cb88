#pragma once
// Settings, recent files and recovery files for an editor suite: a test location of this
// process's own, never the user's, and never that of another checkout testing at the same time.

#include "app/document/document_manager.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QString>

namespace test_support {

// In initTestCase: this process's own files, named after the suite.
inline void isolateSettings(const char* suite) {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("InterplayTests");
    QCoreApplication::setApplicationName(QString("%1-%2").arg(suite).arg(QCoreApplication::applicationPid()));
}

// In init: every case starts with no settings and no recovery file.
inline void clearSettings() {
    QSettings().clear();
    QFile::remove(interplay::DocumentManager::recoveryFilePath());
}

// In cleanupTestCase: nothing is left behind.
inline void removeSettings() {
    QFile::remove(QSettings().fileName());
    QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
}

}  // namespace test_support
