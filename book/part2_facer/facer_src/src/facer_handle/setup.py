from glob import glob
import os

from setuptools import setup

package_name = 'facer_handle'

setup(
    name=package_name,
    version='0.0.0',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages',
            ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        # 人脸模型文件随功能包一起安装到 share/facer_handle/data
        (os.path.join('share', package_name, 'data'), glob('data/*.xml')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='facer',
    maintainer_email='facer@example.com',
    description='识别图像',
    license='Apache License 2.0',
    tests_require=['pytest'],
    entry_points={
        'console_scripts': [
            'identify_image = facer_handle.identify_image:main',
        ],
    },
)
